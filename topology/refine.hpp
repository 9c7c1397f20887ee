#pragma once
/// \file
/// One refinement pass over the cloth by its sizing field.

#include "topology/cloth_complex.hpp"
#include "topology/refinement_options.hpp"
#include "topology/sizing_field.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Computes the sizing field of `options` (compute_sizing, sizing_field.hpp), then bisects the
/// longest rest-space edge of each triangle coarser than the field wants (face_metric_length2 > 1),
/// skipping edges shorter than twice min_edge_length_m and stopping at max_particles. A
/// bisection first bisects the neighbour across the edge when the edge is not its longest too
/// (Rivara's longest-edge propagation path), so the mesh stays conforming and no triangle gets
/// worse than half the smallest initial angle. Masses, rest areas and springs are updated locally
/// after each split (split_edge). Triangle cloths only.
RefinementReport refine(ClothComplex& lcc, const RefinementOptions& options,
                        const SpringSettings& settings, const SizingInputs& inputs = {});

/// Bisects, along its longest-edge propagation path, the longest edge of each triangle around
/// `vertex` whose rest length is at least twice `min_edge_length_m`, until the cloth has
/// `max_particles`: a finer fan there (e.g. at a crack tip). Returns the number of bisections.
int refine_around_vertex(ClothComplex& lcc, Vertex_handle vertex, double min_edge_length_m,
                         int max_particles, const SpringSettings& settings);

}  // namespace tissu
