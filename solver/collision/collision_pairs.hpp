#pragma once
/// \file
/// Broad phase of self-collision: the vertex-triangle and edge-edge pairs of the cloth whose swept
/// boxes overlap during a step, found through a spatial hash. CGAL-free.

#include <vector>

#include "solver/collision/contact_pair.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Every vertex-triangle pair (the vertex not a corner of the triangle) and edge-edge pair (no
/// shared end) of `model`'s surface whose boxes, swept from `start_x` to `end_x` (3#P, m) and
/// grown by `margin_m`, overlap. Primitives are hashed into a uniform grid of cells twice the
/// mean edge length (Teschner et al. 2003, "Optimized spatial hashing for collision detection of
/// deformable objects"). Each pair comes once, in the order of its first primitive then of the
/// cells, whatever the thread count. Left out: pairs of pinned particles only, and pairs closer
/// than `material_gap_m` in material coordinates (model.rest_x, when the model has them).
///
/// The second rule keeps the cloth's own neighbourhood out of contact. Primitives that close in
/// the material are one piece of cloth, not two layers that met; it is what the shared-corner
/// rule says for an intact mesh, extended across cuts and tears: the two lips of a crack share
/// their material points, and would otherwise count as touching the moment the crack opens,
/// gluing it shut. Pieces that meet again still collide, except where the same material points
/// meet (the row of primitives along the lips).
std::vector<CandidatePair> collision_candidates(const SpringModel& model,
                                                const Eigen::VectorXd& start_x,
                                                const Eigen::VectorXd& end_x, double margin_m,
                                                double material_gap_m);

}  // namespace tissu
