#pragma once
/// \file
/// How stretched edges and faces are: for strain colouring, refinement and tearing.

#include <vector>

#include "topology/cloth_complex.hpp"

namespace tissu {

/// Engineering strain of the dart's edge, |x_a - x_b| / |X_a - X_b| - 1 with x current and X
/// material coordinates. Dimensionless; > 0 stretched, < 0 compressed.
double edge_engineering_strain(const ClothComplex& lcc, Dart_const_handle dart);

/// Per face, in one_dart_per_cell<2> order (the order of current_mesh()), the mean engineering
/// strain of its edges (edge_engineering_strain).
std::vector<float> face_edge_strain(const ClothComplex& lcc);

}  // namespace tissu
