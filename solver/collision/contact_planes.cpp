#include "solver/collision/contact_planes.hpp"

#include <algorithm>

#include "solver/parallel.hpp"

namespace tissu {

void find_contact_planes(const SpringModel& model, const std::vector<Obstacle>& obstacles,
                         double stiffness, double time_step_s, double end_time_s,
                         const Eigen::VectorXd& start_x, const Eigen::VectorXd& first_iterate,
                         std::vector<ContactPlane>& planes, ObstacleDistanceCache* distances) {
  planes.clear();
  if (obstacles.empty() || !(stiffness > 0.0)) return;
  std::vector<ObstaclePlacement> before, after;
  for (const Obstacle& obstacle : obstacles) {
    before.push_back(place(obstacle, end_time_s - time_step_s));
    after.push_back(place(obstacle, end_time_s));
  }
  const double per_kg = stiffness / (time_step_s * time_step_s);  // beta / h^2 (1/s^2)
  // particles in parallel, each into its own slots, gathered in order afterwards: deterministic
  const int particles = model.particle_count();
  const std::size_t per_particle = obstacles.size();
  std::vector<ContactPlane> slots(particles * per_particle);
  std::vector<char> filled(slots.size(), 0);
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.pinned[p]) continue;
    const Eigen::Vector3d start = start_x.segment<3>(3 * p);
    const Eigen::Vector3d x0 = first_iterate.segment<3>(3 * p);
    const double travel_m = (x0 - start).norm();
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
      const Obstacle& obstacle = obstacles[k];
      // linearised at x_0, where the step's solution is first looked for; but no plane where it
      // would put the step's start (outside: the last step's contacts put it there; moved with
      // the obstacle's surface to the step's end) more than the thickness below it: x_0 has gone
      // round a curved obstacle or past its middle, no plane holds the particle's whole path, and
      // the plane would throw it where it never was. The projection after the step keeps it out,
      // as it does without the penalty. (A particle sliding on a ball starts a little below the
      // tangent plane ahead of it, by (R + t)(1 - cos) of the angle it slides.)
      const double plane_reach_m = 2.0 * obstacle.thickness_m + travel_m;
      const ParticleQueries queries{distances, static_cast<int>(k), p};
      if (!(queries.distance_at_least_m(obstacle, after[k], end_time_s, x0) < plane_reach_m)) {
        continue;
      }
      const SurfaceDistance at_x0 = queries.distance(obstacle, after[k], end_time_s, x0);
      if (!(at_x0.distance_m < plane_reach_m)) continue;
      const Eigen::Vector3d from = obstacle.motion.moves() || obstacle.animation
                                       ? carry_with_surface(obstacle, before[k], after[k], start)
                                       : start;
      const Eigen::Vector3d point = x0 + (obstacle.thickness_m - at_x0.distance_m) * at_x0.normal;
      if (!((point - from).dot(at_x0.normal) <= obstacle.thickness_m)) continue;
      ContactPlane& plane = slots[p * per_particle + k];
      filled[p * per_particle + k] = 1;
      plane.particle = p;
      plane.obstacle = static_cast<int>(k);
      plane.normal = at_x0.normal;
      plane.point = point;
      plane.stiffness_n_per_m = per_kg * model.mass[p];
    }
  }
  for (std::size_t slot = 0; slot < slots.size(); ++slot) {
    if (filled[slot]) planes.push_back(slots[slot]);
  }
}

double add_contact_potential(const std::vector<ContactPlane>& planes, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient) {
  double energy_j = 0.0;
  for (const ContactPlane& plane : planes) {
    const double depth_m = contact_depth_m(plane, x.segment<3>(3 * plane.particle));
    if (depth_m == 0.0) continue;
    energy_j += 0.5 * plane.stiffness_n_per_m * depth_m * depth_m;
    if (gradient != nullptr) {
      gradient->segment<3>(3 * plane.particle) -=
          (plane.stiffness_n_per_m * depth_m) * plane.normal;
    }
  }
  return energy_j;
}

void contact_normal_impulses(const SpringModel& model, const std::vector<ContactPlane>& planes,
                             int obstacle_count, double time_step_s, const Eigen::VectorXd& x,
                             Eigen::MatrixXd& impulse_m_per_s) {
  impulse_m_per_s.setZero(obstacle_count, model.particle_count());
  for (const ContactPlane& plane : planes) {
    const double depth_m = contact_depth_m(plane, x.segment<3>(3 * plane.particle));
    impulse_m_per_s(plane.obstacle, plane.particle) +=
        time_step_s * plane.stiffness_n_per_m * depth_m * model.inverse_mass[plane.particle];
  }
}

}  // namespace tissu
