#include "solver/collision/obstacle_distance_cache.hpp"

#include <cmath>
#include <limits>

namespace tissu {
namespace {

constexpr double unknown_m = -std::numeric_limits<double>::infinity();

const void* identity_of(const Obstacle& obstacle) {
  if (obstacle.animation) return obstacle.animation.get();
  return obstacle.surface.get();
}

}  // namespace

void ObstacleDistanceCache::prepare(const SpringModel& model,
                                    const std::vector<Obstacle>& obstacles) {
  std::vector<const void*> identities;
  for (const Obstacle& obstacle : obstacles) identities.push_back(identity_of(obstacle));
  const int particles = model.particle_count();
  // (a model never given an identity may be any model: nothing is kept for it)
  if (model.identity != 0 && model.identity == m_model && identities == m_obstacles &&
      particles == m_particles) {
    return;
  }
  m_model = model.identity;
  m_obstacles = std::move(identities);
  m_particles = particles;
  m_queries.assign(obstacles.size() * static_cast<std::size_t>(particles),
                   Query{Eigen::Vector3d::Zero(), unknown_m, 0.0});
}

double ObstacleDistanceCache::distance_at_least_m(int k, int p, const Obstacle& obstacle,
                                                  const ObstaclePlacement& placement, double time_s,
                                                  const Eigen::Vector3d& x) const {
  if (obstacle.shape != ObstacleShape::mesh) return unknown_m;
  const Query& last = m_queries[static_cast<std::size_t>(k) * m_particles + p];
  if (last.distance_m == unknown_m) return unknown_m;
  const Eigen::Vector3d local_m = placement.pose.apply_inverse(x);
  double moved_m = (local_m - last.local_m).norm();
  if (obstacle.animation) {
    // instants within 1e-9 s share a surface: room for that, and for round-off
    moved_m += (1.0 + 1e-9) * obstacle.animation->fastest_speed_m_per_s() *
               (std::abs(time_s - last.time_s) + 2e-9);
  }
  // room for the round-off of the frames and of the distances: a nanometre, more far from the
  // origin (an obstacle may lie up to 1e6 m from it)
  const double round_off_m = 1e-9 + 1e-15 * (local_m.norm() + last.local_m.norm());
  return last.distance_m - moved_m - round_off_m;
}

void ObstacleDistanceCache::record(int k, int p, const Obstacle& obstacle,
                                   const ObstaclePlacement& placement, double time_s,
                                   const Eigen::Vector3d& x, double distance_m) {
  if (obstacle.shape != ObstacleShape::mesh) return;
  if (!std::isfinite(distance_m)) distance_m = unknown_m;
  m_queries[static_cast<std::size_t>(k) * m_particles + p] = {placement.pose.apply_inverse(x),
                                                              distance_m, time_s};
}

}  // namespace tissu
