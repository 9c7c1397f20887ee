#pragma once
/// \file
/// Keeps the cloth from passing through itself: after each step, close pairs are pushed apart and
/// crossings during the step are stopped. CGAL-free.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "solver/collision/collision_pairs.hpp"
#include "solver/collision/contact_pair.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

struct SelfCollisionOptions {
  bool enabled = false;
  /// distance kept between parts of the cloth that are not neighbours (m): its thickness
  double thickness_m = 0.004;
  double friction = 0.1;  ///< Coulomb coefficient between two layers of the cloth, dimensionless
  /// passes of continuous collision impulses before the remaining pairs are frozen into rigid
  /// impact zones
  int impulse_passes = 4;
  /// extra distance the cached pairs cover (m), at most half the mean edge: they serve until a
  /// particle moves half of it
  double skin_m = 0.01;
};

/// Broad-phase pairs kept from step to step: a neighbour list with a skin (Verlet 1967). Each
/// particle has a box it may wander half the skin out of (per axis) before its pairs must be found
/// again; those particles' pairs alone are then searched again (a cloth settling while its hem
/// still slides pays for the hem), and the whole cloth only when many have left at once.
struct SelfCollisionCache {
  /// every pair whose boxes, grown by thickness + skin around `boxes`, overlap
  std::vector<CandidatePair> pairs;
  /// for each pair, the distance between its primitives with their particles at their boxes, when
  /// all four boxes are points, else 0 (m): while its corners stray from those points by less
  /// than the gap less the thickness, the pair cannot touch
  std::vector<double> gap_m;
  /// each particle's box when its pairs were found (m); empty: none. A box that is a step's whole
  /// path rather than a point is searched again at the next step, to shrink back to a point once
  /// its particle slows down.
  ParticleBoxes boxes;
  std::uint64_t built_for_model = 0;  ///< SpringModel::identity they were found on (0 = none)
  double skin_m = 0.0;  ///< the skin they were found with: the option's, at most half the mean edge
  /// Where the frame the boxes are drawn in stands at the next step's start (m): they bound
  /// positions less this offset. Each step the frame moves by the cloth's median step
  /// (frame_step_m), so a cloth that falls or is carried as a whole keeps its pairs and their
  /// gaps: which primitives come close depends only on where the particles are relative to each
  /// other, the same in any frame moving at a constant velocity over the step.
  Eigen::Vector3d frame_m = Eigen::Vector3d::Zero();
};

/// The frame's step from `start_x` to `end_x` (3#P, m): per axis, the median of the particles'
/// steps (of up to 1,024 of them), when one of them exceeds `least_m`, else none (m). A cloth
/// falling or carried at 1 m/s moves about 3 cm per step at 30 steps per second, farther than half
/// the skin: in a fixed frame every particle would leave its box and the whole cloth be searched
/// again over its paths each step. Below `least_m` (half the skin) the frame stands still: the
/// particles of a cloth pulled apart, or settling, would otherwise leave their boxes as the median
/// wanders.
Eigen::Vector3d frame_step_m(const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x,
                             double least_m);

/// The positions `x` (3#P, m) in a frame whose origin stands at `origin_m`: x_p - origin_m.
Eigen::VectorXd relative_to(const Eigen::VectorXd& x, const Eigen::Vector3d& origin_m);

/// The kept pairs whose primitives may come within `reach_m` of each other on the way from
/// `start_x` to `end_x` (3#P, m, in the cache's frame: relative_to its frame_m at the step's start
/// and end), in order: what a step tests exactly. A pair is ruled out when
/// - its gap at its particles' boxes, less the farthest a corner of each primitive strays from
///   its box's point over the step, exceeds the reach: each primitive's closest point is a
///   convex combination of its corners, and a corner strays farthest at the start or the end of
///   its straight path. On a flat sheet most kept pairs are coplanar neighbours a good part of an
///   edge apart, whose boxes overlap all the same; or
/// - the boxes of its primitives over the step do not come within the reach.
std::vector<CandidatePair> kept_pairs_within_reach(const SelfCollisionCache& cache,
                                                   const Eigen::VectorXd& start_x,
                                                   const Eigen::VectorXd& end_x, double reach_m);

/// What one step's self-collision handling found.
struct SelfCollisionReport {
  int candidates = 0;      ///< pairs tested exactly: kept_pairs_within_reach of the thickness
  int proximities = 0;     ///< pairs closer than the thickness, pushed apart
  int impacts = 0;         ///< crossings during the step stopped by impulses, over all passes
  int zone_particles = 0;  ///< particles moved rigidly in impact zones
  bool resolved = true;    ///< false when crossings were left after every zone pass
  double wall_ms = 0.0;    ///< wall time spent (ms)
};

/// Self-collision response after the integrator has moved the particles from `start_x` to
/// `state.x` (3#P, m) in a step of `time_step_s` (Bridson, Fedkiw & Anderson 2002, "Robust
/// treatment of collisions, contact and friction for cloth animation", sections 6-7, simplified):
/// 1. proximity: vertex-triangle and edge-edge pairs closer than the thickness at the end are
///    pushed apart along their normal (positions only: no energy is added), their approaching
///    relative velocity is removed with an inelastic impulse, and friction acts on their relative
///    tangential velocity;
/// 2. continuous collision: pairs that cross during the step (first_impact) get impulses that
///    cancel their approaching relative displacement, for up to `impulse_passes` passes;
/// 3. impact zones (Provot 1997): particles of pairs still crossing are merged into zones that
///    move as one, at their mass-weighted mean displacement (translation only), until none cross.
/// Impulses are mass-weighted and each particle's share is averaged over its pairs, so the
/// result does not depend on the order of the pairs or on the thread count. Pinned particles act
/// as infinitely heavy: they are not moved, and a zone holding some moves as they did in the step
/// (their mean displacement: a still pin's zone stays where it started). So do the particles an
/// obstacle holds (`holding_normal`, 3 x #P: the obstacle's outward normal, 0 where none holds;
/// or empty), so that a zone an arm holds moves with the arm, except that steps 1 and 2 may move
/// them away from their obstacle, never into it: a layer that fell through another onto the floor
/// within one step is lifted back above it.
/// Velocities change with positions (v += dx / h) except for the proximity push.
SelfCollisionReport resolve_self_collisions(const SpringModel& model,
                                            const SelfCollisionOptions& options, double time_step_s,
                                            const Eigen::VectorXd& start_x,
                                            const Eigen::Matrix3Xd& holding_normal,
                                            SelfCollisionCache& cache, State& state);

}  // namespace tissu
