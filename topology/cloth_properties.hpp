#pragma once
/// \file
/// Rest areas, lumped masses and springs of a cloth complex, computed from material coordinates so
/// that they do not depend on the current deformation.

#include <Eigen/Core>
#include <vector>

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Area of the face of `dart` in material coordinates (m^2): the norm of the polygon's vector area
/// 1/2 sum_k p_k x p_{k+1}, exact for triangles and planar quads.
double face_rest_area(const ClothComplex& lcc, Dart_const_handle dart);

/// Sets every face's rest area and areal density.
void assign_face_rest(ClothComplex& lcc, double areal_density_kg_per_m2);

/// Lumped masses (course: m = sum_i m_i): each face gives density x rest area / (its vertex count)
/// to each of its vertices, so the total is density x total rest area.
void lump_masses(ClothComplex& lcc);

/// Fills the spring slots of every edge and every dart from `settings` and the material
/// coordinates.
void assign_springs(ClothComplex& lcc, const SpringSettings& settings);

/// Fills the spring slots of the dart's edge (structural, bending) and of the dart itself (shear
/// diagonal, coupling); see assign_springs. The edge's springs come out the same, to the bit,
/// from either of its darts.
void assign_dart_springs(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings);

/// Sets the mass of `vertex` to its share of each incident face: sum of density x rest area /
/// (vertex count of the face), the per-vertex form of lump_masses().
void lump_vertex_mass(ClothComplex& lcc, Vertex_handle vertex);

/// The vertex that follows the dart's edge in the dart's face (the apex for a triangle).
Vertex_handle vertex_after_edge(ClothComplex& lcc, Dart_handle dart);

/// Rest length of the dart's edge, the distance of its ends' material coordinates (m).
double edge_rest_length_m(const ClothComplex& lcc, Dart_const_handle dart);

/// The vertex whose material coordinates are nearest `rest_point_m` (the first in container order
/// among equally near ones). The complex must have a vertex.
Vertex_handle nearest_vertex(ClothComplex& lcc, const Eigen::Vector3d& rest_point_m);

/// The darts starting at `vertex`: one per incident face.
std::vector<Dart_handle> darts_leaving(ClothComplex& lcc, Vertex_handle vertex);

/// Sum of particle masses (kg).
double complex_total_mass(const ClothComplex& lcc);

/// Sum over faces of areal density x rest area (kg): what the particle masses must add up to.
double complex_expected_mass(const ClothComplex& lcc);

}  // namespace tissu
