#pragma once
/// \file
/// What each particle's last distance query to each mesh obstacle found, so that a query whose
/// answer is already known to be "farther than that" is skipped. CGAL-free.
///
/// A signed distance is 1-Lipschitz in the point (its sign flips only on the surface), and an
/// animated surface whose points move at most v_max moves it by at most v_max |t - t_q|; a rigid
/// motion moves it not at all in the obstacle's own frame. So a query at x_q and t_q that found
/// d_q bounds every later one, in that frame:
///   d(x, t) >= d_q - |x - x_q| - v_max |t - t_q|.
/// A T-shirt's particles hang mostly farther from the body than a contact could reach within a
/// step; the bound skips most of their queries (docs/benchmarks.md), with the same steps to the
/// bit.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "solver/collision/obstacle.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

class ObstacleDistanceCache {
 public:
  /// Keeps what is known when the model (its identity, not 0) and the obstacles (their surfaces and
  /// animations) are the ones of the last call, else forgets it all. Call before each step's
  /// queries (not thread-safe); the others may be called in parallel for different particles.
  void prepare(const SpringModel& model, const std::vector<Obstacle>& obstacles);

  /// A lower bound on particle p's signed distance from `obstacle` (the k-th) at x (m, world) when
  /// `placement` (at `time_s`) puts it there: -infinity for anything but a mesh, or if nothing is
  /// known yet.
  double distance_at_least_m(int k, int p, const Obstacle& obstacle,
                             const ObstaclePlacement& placement, double time_s,
                             const Eigen::Vector3d& x) const;

  /// Records that particle p's query at x (m, world) found `distance_m` from obstacle k placed by
  /// `placement` at `time_s`. Nothing for anything but a mesh.
  void record(int k, int p, const Obstacle& obstacle, const ObstaclePlacement& placement,
              double time_s, const Eigen::Vector3d& x, double distance_m);

 private:
  struct Query {
    Eigen::Vector3d local_m;  ///< where, in the obstacle's own frame
    double distance_m;        ///< what it found (signed; -infinity: nothing known)
    double time_s;            ///< when
  };
  std::uint64_t m_model = 0;
  std::vector<const void*> m_obstacles;  ///< each obstacle's surface or animation
  int m_particles = 0;
  std::vector<Query> m_queries;  ///< k #P + p
};

/// One particle's queries of one obstacle, remembered in `cache` if there is one.
struct ParticleQueries {
  ObstacleDistanceCache* cache;
  int obstacle;
  int particle;

  /// A lower bound on the distance at x (m) that costs no query: a mesh's box
  /// (surface_distance_at_least_m()), or the particle's queries before where they say more.
  double distance_at_least_m(const Obstacle& o, const ObstaclePlacement& placement, double time_s,
                             const Eigen::Vector3d& x) const {
    const double box_m = surface_distance_at_least_m(o, placement, x);
    if (cache == nullptr) return box_m;
    return std::max(box_m, cache->distance_at_least_m(obstacle, particle, o, placement, time_s, x));
  }

  /// surface_distance(), recorded.
  SurfaceDistance distance(const Obstacle& o, const ObstaclePlacement& placement, double time_s,
                           const Eigen::Vector3d& x) const {
    const SurfaceDistance found = surface_distance(o, placement, x);
    if (cache != nullptr) {
      cache->record(obstacle, particle, o, placement, time_s, x, found.distance_m);
    }
    return found;
  }
};

}  // namespace tissu
