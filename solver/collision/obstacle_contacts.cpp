#include "solver/collision/obstacle_contacts.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "solver/parallel.hpp"

namespace tissu {
namespace {

/// Where the segment from `from` to `to` (not of zero length) first comes within `offset_m` of the
/// surface of `obstacle` (a signed distance <= offset), if it does: sphere tracing (Hart 1996)
/// along it, each advance by the distance to the offset surface, which cannot overshoot it. The
/// obstacle is taken where `placement` puts it, at the end of the step; `from_distance_m` is the
/// signed distance from `from` there. A path still creeping along the surface after 64 advances
/// counts as reaching it there.
std::optional<Eigen::Vector3d> trace_to_offset(const Obstacle& obstacle,
                                               const Eigen::Vector3d& from,
                                               const Eigen::Vector3d& to,
                                               const ObstaclePlacement& placement,
                                               double from_distance_m, double offset_m) {
  const double length_m = (to - from).norm();
  double clearance_m = from_distance_m - offset_m;
  double travelled = 0.0;  // fraction of the path
  for (int step = 0; step < 64; ++step) {
    const Eigen::Vector3d here = from + travelled * (to - from);
    if (step > 0) clearance_m = surface_distance(obstacle, placement, here).distance_m - offset_m;
    if (clearance_m <= 1e-9 * length_m) return here;
    travelled += clearance_m / length_m;
    if (travelled >= 1.0) return std::nullopt;
  }
  return from + travelled * (to - from);
}

/// Where a particle moving from `from` to `to` during the step first comes within the thickness of
/// `obstacle`, if it does, when both ends are clear of it (a thin obstacle crossed in one step).
std::optional<Eigen::Vector3d> first_contact_on_path(const Obstacle& obstacle,
                                                     const Eigen::Vector3d& from,
                                                     const Eigen::Vector3d& to,
                                                     const ObstaclePlacement& placement,
                                                     double from_distance_m) {
  const double length_m = (to - from).norm();
  // a particle that starts in contact, at the thickness to round-off (where the last step left
  // it) or closer, and ends clear is leaving: the end-position test handles its contacts
  if (!(length_m > 0.0) ||
      from_distance_m - obstacle.thickness_m <= 1e-9 * (obstacle.thickness_m + length_m)) {
    return std::nullopt;
  }
  return trace_to_offset(obstacle, from, to, placement, from_distance_m, obstacle.thickness_m);
}

/// Whether a particle moving from `from` to `to` during the step goes into `obstacle` itself (a
/// signed distance <= 0 on the way). A path that ends clear and only dips into the thickness
/// layer, as a straight chord past a curved surface does, did not cross anything.
bool path_enters(const Obstacle& obstacle, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                 const ObstaclePlacement& placement, double from_distance_m) {
  return (to - from).norm() > 0.0 &&
         trace_to_offset(obstacle, from, to, placement, from_distance_m, 0.0).has_value();
}

/// How far carry_with_surface() can move `start` over a step of `h` (m), without its closest-point
/// query: the rigid motion's displacement of `start`, plus what the animation moves any point of
/// the surface in the step (at most its fastest speed times h; with room for round-off and for the
/// animation's instants within 1e-9 s counting as one).
double carry_bound_m(const Obstacle& obstacle, const ObstaclePlacement& before,
                     const ObstaclePlacement& after, double h, const Eigen::Vector3d& start) {
  double bound_m = (after.pose.apply(before.pose.apply_inverse(start)) - start).norm();
  if (obstacle.animation && before.surface != after.surface) {
    bound_m += (1.0 + 1e-9) * obstacle.animation->fastest_speed_m_per_s() * (h + 2e-9);
  }
  return bound_m;
}

/// One obstacle, at `before` and `after` at the start and the end (`time_s`) of the step, against
/// one particle that moved from `start` during the step: the outward normal where they touched, or
/// nothing. The particle's path is measured relative to the obstacle, from where `start` would be
/// at the end of the step had it moved with the obstacle's surface.
std::optional<Eigen::Vector3d> resolve(const Obstacle& obstacle, const ObstaclePlacement& before,
                                       const ObstaclePlacement& after, double h, double time_s,
                                       const Eigen::Vector3d& start, double step_normal_impulse,
                                       const ParticleQueries& queries,
                                       Eigen::Ref<Eigen::Vector3d> x,
                                       Eigen::Ref<Eigen::Vector3d> v) {
  // A signed distance changes by at most the distance moved (it is 1-Lipschitz: its sign flips on
  // the surface only), so a path shorter than the end's clearance never came within the thickness:
  // first against a bound on the path's length (with a bound on the clearance, then the
  // clearance, by the mesh's box or by the particle's queries before), then against the path.
  const bool moves = obstacle.motion.moves() || obstacle.animation;
  const double path_bound_m =
      (x - start).norm() + (moves ? carry_bound_m(obstacle, before, after, h, start) : 0.0);
  if (queries.distance_at_least_m(obstacle, after, time_s, x) - obstacle.thickness_m >
      path_bound_m) {
    return std::nullopt;
  }
  SurfaceDistance surface = queries.distance(obstacle, after, time_s, x);
  const double end_clearance_m = surface.distance_m - obstacle.thickness_m;
  if (moves && end_clearance_m > path_bound_m) return std::nullopt;
  const Eigen::Vector3d from = moves ? carry_with_surface(obstacle, before, after, start) : start;
  if (end_clearance_m > (x - from).norm()) return std::nullopt;
  const bool ends_near = surface.distance_m < obstacle.thickness_m;
  const SurfaceDistance at_start = queries.distance(obstacle, after, time_s, from);
  // ending near the far side of a part thinner than the step means it went through
  const bool crossed =
      ends_near && at_start.distance_m >= 0.0 && surface.normal.dot(at_start.normal) < 0.0;
  if (!ends_near || crossed) {
    // a path that ends clear met the obstacle only if it went into it (through a thin part): one
    // that grazed its thickness, as a particle pulled round a moving leg does relative to the leg,
    // is not held back (it was, and the leg dragged it along: docs/benchmarks.md)
    const bool went_in = ends_near || path_enters(obstacle, from, x, after, at_start.distance_m);
    if (const auto contact =
            went_in ? first_contact_on_path(obstacle, from, x, after, at_start.distance_m)
                    : std::nullopt) {
      x = *contact;  // where the path first came within the thickness, on its own side
      surface = surface_distance(obstacle, after, x);
    } else if (!ends_near) {
      return std::nullopt;
    } else {
      // it started touching: measure it on the side it started from
      surface = at_start;
      surface.distance_m += (x - from).dot(at_start.normal);
    }
  }
  const Eigen::Vector3d& n = surface.normal;
  const double pushed_m = std::max(0.0, obstacle.thickness_m - surface.distance_m);
  x += pushed_m * n;

  const Eigen::Vector3d v_obstacle =
      surface_velocity(obstacle, before, after, surface, x, time_s, h);
  const Eigen::Vector3d relative = v - v_obstacle;
  const double v_n = relative.dot(n);
  // the normal impulse per unit mass: the approach it stops, or the push out of the surface over
  // the step if that is more (a cloth squeezed between two surfaces is pushed out of each at
  // every step without approaching either, and is held by friction), plus what the step's own
  // contact penalty gave
  const double dv_n = std::max(-v_n, pushed_m / h) + step_normal_impulse;
  if (!(dv_n > 0.0)) return n;  // leaving, and not pushed
  const Eigen::Vector3d v_t = relative - v_n * n;
  const double speed_t = v_t.norm();
  const Eigen::Vector3d v_t_after =
      speed_t <= obstacle.static_friction * dv_n
          ? Eigen::Vector3d::Zero()
          : Eigen::Vector3d(std::max(0.0, 1.0 - obstacle.kinetic_friction * dv_n / speed_t) * v_t);
  v = v_obstacle + std::max(0.0, v_n) * n + v_t_after;  // an approach removed, a departure kept
  x += h * (v_t_after - v_t);
  return n;
}

/// Each obstacle placed once at each end of the step, for the step's queries.
struct StepPlacements {
  std::vector<ObstaclePlacement> before, after;
  StepPlacements(const std::vector<Obstacle>& obstacles, double time_step_s, double time_s) {
    for (const Obstacle& obstacle : obstacles) {
      before.push_back(place(obstacle, time_s - time_step_s));
      after.push_back(place(obstacle, time_s));
    }
  }
};

/// Every obstacle against particle p (see resolve_obstacle_contacts); returns how many touched it
/// and sets `holding_normal` to the last one's outward normal. `step_normal_impulse` is p's column
/// of resolve_obstacle_contacts()'s (m/s), or null; `distances` remembers p's queries, or is null.
int resolve_particle(const std::vector<Obstacle>& obstacles, const StepPlacements& placements,
                     double time_step_s, double time_s, int p, const Eigen::Vector3d& start,
                     const double* step_normal_impulse, ObstacleDistanceCache* distances,
                     Eigen::Ref<Eigen::Vector3d> x, Eigen::Ref<Eigen::Vector3d> v,
                     Eigen::Ref<Eigen::Vector3d> holding_normal) {
  const auto& [before, after] = placements;
  const auto queries_of = [&](std::size_t k) {
    return ParticleQueries{distances, static_cast<int>(k), p};
  };
  int touched = 0;
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const double impulse = step_normal_impulse != nullptr ? step_normal_impulse[k] : 0.0;
    if (const auto normal = resolve(obstacles[k], before[k], after[k], time_step_s, time_s, start,
                                    impulse, queries_of(k), x, v)) {
      holding_normal = *normal;
      ++touched;
    }
  }
  if (touched == 0 || obstacles.size() < 2) return touched;
  // Pushed out of one obstacle deep into another (a crease where two overlap: an armpit, the
  // parts of a body mesh), it could be pushed back and forth without end: it goes back to where
  // it started the step, carried by the surface it ended in, and moves with that surface. A
  // particle squeezed between two surfaces closer than their thicknesses, and inside neither by
  // more than a thickness, is left where the last one put it (a hand holding cloth).
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    if (queries_of(k).distance_at_least_m(obstacles[k], after[k], time_s, x) > 0.0) {
      continue;  // outside
    }
    const SurfaceDistance inside = queries_of(k).distance(obstacles[k], after[k], time_s, x);
    if (!(inside.distance_m < -obstacles[k].thickness_m)) continue;
    x = carry_with_surface(obstacles[k], before[k], after[k], start);
    v = surface_velocity(obstacles[k], before[k], after[k],
                         surface_distance(obstacles[k], after[k], x), x, time_s, time_step_s);
    break;
  }
  return touched;
}

}  // namespace

int resolve_obstacle_contacts(const SpringModel& model, const std::vector<Obstacle>& obstacles,
                              double time_step_s, double time_s, const Eigen::VectorXd& start_x,
                              State& state, Eigen::Matrix3Xd& holding_normal,
                              const Eigen::MatrixXd& step_normal_impulse,
                              ObstacleDistanceCache* distances) {
  const int particles = model.particle_count();
  holding_normal.setZero(3, particles);
  if (obstacles.empty()) return 0;
  const bool impulses = step_normal_impulse.size() > 0;
  const StepPlacements placements(obstacles, time_step_s, time_s);
  int contacts = 0;
#pragma omp parallel for schedule(static) reduction(+ : contacts) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.pinned[p]) continue;
    contacts += resolve_particle(
        obstacles, placements, time_step_s, time_s, p, start_x.segment<3>(3 * p),
        impulses ? &step_normal_impulse(0, p) : nullptr, distances, state.x.segment<3>(3 * p),
        state.v.segment<3>(3 * p), holding_normal.col(p));
  }
  return contacts;
}

void resolve_obstacle_contacts_of(const std::vector<int>& moved,
                                  const std::vector<Obstacle>& obstacles, double time_step_s,
                                  double time_s, const Eigen::VectorXd& start_x, State& state,
                                  ObstacleDistanceCache* distances) {
  if (obstacles.empty() || moved.empty()) return;
  const StepPlacements placements(obstacles, time_step_s, time_s);
  const int count = static_cast<int>(moved.size());
#pragma omp parallel for schedule(static) if (count >= min_parallel_items)
  for (int k = 0; k < count; ++k) {
    const int p = moved[k];
    const Eigen::Vector3d x = state.x.segment<3>(3 * p);
    bool inside = false;
    for (std::size_t o = 0; o < obstacles.size() && !inside; ++o) {
      const ParticleQueries queries{distances, static_cast<int>(o), p};
      const ObstaclePlacement& after = placements.after[o];
      inside = !(queries.distance_at_least_m(obstacles[o], after, time_s, x) > 0.0) &&
               queries.distance(obstacles[o], after, time_s, x).distance_m < 0.0;
    }
    if (!inside) continue;  // within an obstacle's thickness at most: left to the cloth's layers
    Eigen::Vector3d unused_normal;
    resolve_particle(obstacles, placements, time_step_s, time_s, p, start_x.segment<3>(3 * p),
                     nullptr, distances, state.x.segment<3>(3 * p), state.v.segment<3>(3 * p),
                     unused_normal);
  }
}

}  // namespace tissu
