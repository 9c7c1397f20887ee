#pragma once
/// \file
/// How stretched and how bent the cloth is at its edges and faces: the measures refinement,
/// coarsening, tearing and strain colouring decide by.

#include <vector>

#include "topology/cloth_complex.hpp"

namespace tissu {

/// Engineering strain of the dart's edge, |x_a - x_b| / |X_a - X_b| - 1 with x current and X
/// material coordinates. Dimensionless; > 0 stretched, < 0 compressed.
double edge_engineering_strain(const ClothComplex& lcc, Dart_const_handle dart);

/// Edge strain |l / l0 - 1| of the dart's edge, l current and l0 rest length (dimensionless): the
/// magnitude of edge_engineering_strain.
double edge_strain(const ClothComplex& lcc, Dart_const_handle dart);

/// Angle between the normals of the two faces of the dart's edge (radians), 0 on the boundary. A
/// face's normal is (b - a) x (c - a) over its first three corners a, b, c from the dart.
double edge_dihedral_angle(const ClothComplex& lcc, Dart_const_handle dart);

/// Per face, in one_dart_per_cell<2> order (the order of current_mesh()), the mean engineering
/// strain of its edges (edge_engineering_strain).
std::vector<float> face_edge_strain(const ClothComplex& lcc);

/// Per face, in the same order, its refinement level log2(A_input / A): 0 on an input face, 1
/// per bisection (each halves the rest area), FaceRest::input_area over rest_area; 0 for a face
/// without an input area.
std::vector<float> face_refinement_level(const ClothComplex& lcc);

/// Per face, in the same order, the sizing term that held it at the last adaptation pass
/// (FaceRest::sizing_term) as its SizingTerm value: 0 none, 1 curvature, 2 velocity, 3 strain,
/// 4 obstacles, 5 maximum edge length.
std::vector<float> face_sizing_term(const ClothComplex& lcc);

}  // namespace tissu
