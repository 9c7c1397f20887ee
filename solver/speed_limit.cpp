#include "solver/speed_limit.hpp"

#include <algorithm>
#include <cmath>

namespace tissu {
namespace {

/// How far the obstacle's surface reaches from its motion's pivot at t = 0 (m); a plane, which
/// has no bound, reaches as far as the cloth does.
double obstacle_reach_m(const Obstacle& obstacle, double cloth_reach_m) {
  const Eigen::Vector3d& pivot = obstacle.motion.pivot_m;
  const double centre_m = (obstacle.position - pivot).norm();
  switch (obstacle.shape) {
    case ObstacleShape::plane:
      return cloth_reach_m;
    case ObstacleShape::sphere:
      return centre_m + obstacle.radius_m;
    case ObstacleShape::capsule:
      return std::max(centre_m, (obstacle.axis_end - pivot).norm()) + obstacle.radius_m;
    case ObstacleShape::box:
      return centre_m + obstacle.half_extents_m.norm();
    case ObstacleShape::mesh: {
      double reach_m = 0.0;
      for (const Eigen::Vector3d& corner : obstacle.surface->triangle_corners()) {
        reach_m = std::max(reach_m, (corner - pivot).norm());
      }
      return reach_m;
    }
  }
  return cloth_reach_m;
}

}  // namespace

double farthest_particle_m(const State& state, const Eigen::Vector3d& point) {
  double reach_m = 0.0;
  for (Eigen::Index p = 0; 3 * p < state.x.size(); ++p) {
    reach_m = std::max(reach_m, (state.x.segment<3>(3 * p) - point).norm());
  }
  return reach_m;
}

SpeedLimit speed_limit_at_start(const SpringModel& model, const SolverParams& params,
                                const State& state) {
  SpeedLimit limit;
  limit.start_time_s = state.time;
  for (int p = 0; p < model.particle_count(); ++p) {
    limit.initial_speed_m_per_s =
        std::max(limit.initial_speed_m_per_s, state.v.segment<3>(3 * p).norm());
  }
  for (const Obstacle& obstacle : params.obstacles) {
    const RigidMotion& motion = obstacle.motion;
    const double reach_m =
        motion.rotates() ? obstacle_reach_m(obstacle, farthest_particle_m(state, motion.pivot_m))
                         : 0.0;
    const double deforming_m_per_s =
        obstacle.animation ? obstacle.animation->fastest_speed_m_per_s() : 0.0;
    limit.obstacle_speed_m_per_s = std::max(
        limit.obstacle_speed_m_per_s, motion.fastest_speed_m_per_s(reach_m) + deforming_m_per_s);
  }
  const Wind& wind = params.environment.wind;
  limit.wind_speed_m_per_s = wind.velocity.norm() * (1.0 + std::abs(wind.gust_amplitude));
  limit.gravity_m_per_s2 = params.environment.gravity.norm();
  limit.release_speed_m_per_s = spring_release_speed_m_per_s(model, state);
  return limit;
}

double spring_release_speed_m_per_s(const SpringModel& model, const State& state) {
  double fastest = 0.0;
  for (int s = 0; s < model.spring_count(); ++s) {
    const int i = model.springs(s, 0), j = model.springs(s, 1);
    const double lighter_kg = std::min(model.mass[i], model.mass[j]);
    if (!(lighter_kg > 0.0) || !(model.stiffness[s] > 0.0)) continue;
    const double stretch_m =
        (state.x.segment<3>(3 * i) - state.x.segment<3>(3 * j)).norm() - model.rest_length[s];
    // its energy 1/2 k stretch^2 all given to the lighter end
    fastest = std::max(fastest, std::abs(stretch_m) * std::sqrt(model.stiffness[s] / lighter_kg));
  }
  return fastest;
}

void widen_for_release(SpeedLimit& limit, const SpringModel& model, const State& state) {
  limit.release_speed_m_per_s =
      std::max(limit.release_speed_m_per_s, spring_release_speed_m_per_s(model, state));
}

double speed_limit_m_per_s(const SpeedLimit& limit, double time_s) {
  const double elapsed_s = std::max(0.0, time_s - limit.start_time_s);
  return limit.margin * (limit.initial_speed_m_per_s + limit.obstacle_speed_m_per_s +
                         limit.handle_speed_m_per_s + limit.wind_speed_m_per_s +
                         limit.gravity_m_per_s2 * elapsed_s + limit.release_speed_m_per_s);
}

std::optional<Overspeed> find_overspeed(const SpeedLimit& limit, const SpringModel& model,
                                        const State& state) {
  Overspeed fastest;
  double fastest2 = -1.0;  // squared speed (m^2/s^2)
  for (int p = 0; p < model.particle_count(); ++p) {
    if (model.inverse_mass[p] == 0.0) continue;
    const double speed2 = state.v.segment<3>(3 * p).squaredNorm();
    if (std::isnan(speed2)) {
      fastest2 = speed2;
      fastest.particle = p;
      break;
    }
    if (speed2 > fastest2) {
      fastest2 = speed2;
      fastest.particle = p;
    }
  }
  if (!(fastest2 >= 0.0) && !std::isnan(fastest2)) return std::nullopt;  // no free particle
  fastest.speed_m_per_s = std::sqrt(fastest2);
  fastest.limit_m_per_s = speed_limit_m_per_s(limit, state.time);
  if (fastest.speed_m_per_s <= fastest.limit_m_per_s) return std::nullopt;
  return fastest;
}

}  // namespace tissu
