#pragma once
/// \file
/// How stretched each face is, for strain colouring (and later for refinement and tearing).

#include <vector>

#include "topology/cloth_complex.hpp"

namespace tissu {

/// Per face, in one_dart_per_cell<2> order (the order of current_mesh()), the mean engineering
/// strain of its edges: mean over edges of |x_a - x_b| / |X_a - X_b| - 1, with x current and X
/// material coordinates. Dimensionless; > 0 stretched, < 0 compressed.
std::vector<float> face_edge_strain(const ClothComplex& lcc);

}  // namespace tissu
