#pragma once
/// \file
/// Walking the cloth complex: the darts around a vertex, the vertex after an edge, the vertex
/// nearest a material point.
///
/// These queries only read the complex. The two whose answers editors edit through (coarsen
/// removes the vertex at darts_leaving(...).front(), refinement splits the edges around the
/// vertex nearest a point) are templates over the complex's constness, as CGAL's own next() and
/// vertex_attribute() are overload pairs: given a `const ClothComplex&` they take and answer const
/// handles, given a `ClothComplex&` mutable ones. One body serves both, with no copy and no cast.
/// The alternatives were worse: a const version plus a mutable overload needs a second body, or a
/// const_cast back from CGAL's const handles (CGAL 5.5 converts only a mutable Dart& or a
/// container index, O(#blocks), to a Dart_handle). The bodies are in complex_navigation.cpp,
/// instantiated there for both constnesses, so the compiler checks that they only read. An editor
/// holding const handles reads through std::as_const(lcc). The internal helpers of refine, coarsen
/// and tear that only ever answer handles to edit take the mutable complex; a query no editor needs
/// a mutable answer from takes and answers const handles.

#include <Eigen/Core>
#include <concepts>
#include <type_traits>
#include <vector>

#include "topology/cloth_complex.hpp"

namespace tissu {

/// ClothComplex or const ClothComplex.
template <class Complex>
concept MaybeConstClothComplex = std::same_as<std::remove_const_t<Complex>, ClothComplex>;

/// Dart handle of a `Complex`'s constness: Dart_const_handle for a const complex.
template <MaybeConstClothComplex Complex>
using Dart_handle_of = std::conditional_t<std::is_const_v<Complex>, Dart_const_handle, Dart_handle>;

/// Vertex handle of a `Complex`'s constness: Vertex_const_handle for a const complex.
template <MaybeConstClothComplex Complex>
using Vertex_handle_of =
    std::conditional_t<std::is_const_v<Complex>, Vertex_const_handle, Vertex_handle>;

/// The darts starting at `vertex`: one per incident face, in the order of CGAL's
/// darts_of_cell<0> from vertex->dart() (so the first is vertex->dart()).
template <MaybeConstClothComplex Complex>
std::vector<Dart_handle_of<Complex>> darts_leaving(Complex& lcc, Vertex_handle_of<Complex> vertex);

/// The vertex that follows the dart's edge in the dart's face (the apex for a triangle).
Vertex_const_handle vertex_after_edge(const ClothComplex& lcc, Dart_const_handle dart);

/// Whether the face of `dart` is a triangle.
bool face_is_triangle(const ClothComplex& lcc, Dart_const_handle dart);

/// Whether the face of `dart` and, inside the cloth, the face across its edge are triangles.
bool edge_between_triangles(const ClothComplex& lcc, Dart_const_handle dart);

/// One dart per edge, the same whichever dart of the edge is given.
Dart_const_handle edge_key(const ClothComplex& lcc, Dart_const_handle dart);

/// Whether an edge joins `a` and `b`.
bool joined_by_edge(const ClothComplex& lcc, Vertex_const_handle a, Vertex_const_handle b);

/// The vertex whose material coordinates are nearest `rest_point_m` (the first in container order
/// among equally near ones). The complex must have a vertex.
template <MaybeConstClothComplex Complex>
Vertex_handle_of<Complex> nearest_vertex(Complex& lcc, const Eigen::Vector3d& rest_point_m);

}  // namespace tissu
