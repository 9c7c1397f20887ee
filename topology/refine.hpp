#pragma once
/// \file
/// One refinement pass over the cloth by strain and curvature.

#include "topology/cloth_complex.hpp"
#include "topology/refinement_options.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Edge strain |l / l0 - 1| of the dart's edge, l current and l0 rest length (dimensionless).
double edge_strain(const ClothComplex& lcc, Dart_const_handle dart);

/// Angle between the normals of the two faces of the dart's edge (radians), 0 on the boundary.
double edge_dihedral_angle(const ClothComplex& lcc, Dart_const_handle dart);

/// Finds the edges over a threshold of `options`, then bisects the longest rest-space edge of
/// each triangle next to one of them, skipping edges shorter than twice min_edge_length_m and
/// stopping at max_particles. A bisection first bisects the neighbour across the edge when the
/// edge is not its longest too (Rivara's longest-edge propagation path), so the mesh stays
/// conforming and no triangle gets worse than half the smallest initial angle. Masses, rest areas
/// and springs are updated locally after each split (split_edge). Triangle cloths only.
RefinementReport refine(ClothComplex& lcc, const RefinementOptions& options,
                        const SpringSettings& settings);

}  // namespace tissu
