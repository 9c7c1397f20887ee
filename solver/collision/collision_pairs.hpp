#pragma once
/// \file
/// Broad phase of self-collision: the vertex-triangle and edge-edge pairs of the cloth whose swept
/// boxes overlap during a step, found through a spatial hash. CGAL-free.

#include <vector>

#include "solver/collision/contact_pair.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Where each particle may be while its pairs serve: an axis-aligned box per particle (m), the
/// segment a step sweeps or a single point.
struct ParticleBoxes {
  Eigen::Matrix3Xd low, high;  ///< 3 x #P corners (m)

  /// The boxes of the straight paths from `start_x` to `end_x` (3#P, m).
  static ParticleBoxes swept(const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x);
  int size() const { return static_cast<int>(low.cols()); }
  /// Whether particle p's box is a path rather than a single point.
  bool is_path(int p) const { return low.col(p) != high.col(p); }
};

/// The mean length of the surface's edges between the centres of their ends' boxes (m).
double mean_edge_length_m(const SpringModel& model, const ParticleBoxes& boxes);

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

/// The same pairs for primitives spanning the particles' `boxes` (a primitive's box is the union
/// of its particles' boxes) instead of their paths over one step.
std::vector<CandidatePair> collision_candidates(const SpringModel& model,
                                                const ParticleBoxes& boxes, double margin_m,
                                                double material_gap_m);

/// Only those of the pairs above that have a particle with `touched[p]` (#P flags): what a
/// neighbour list must find again when some particles leave their boxes (collide with the rest
/// in O(touched primitives), plus building the hash tables in O(#primitives)).
std::vector<CandidatePair> collision_candidates_touching(const SpringModel& model,
                                                         const ParticleBoxes& boxes,
                                                         double margin_m, double material_gap_m,
                                                         const std::vector<char>& touched);

}  // namespace tissu
