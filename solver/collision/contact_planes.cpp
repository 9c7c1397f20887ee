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
      plane.start = from;
    }
  }
  for (std::size_t slot = 0; slot < slots.size(); ++slot) {
    if (filled[slot]) planes.push_back(slots[slot]);
  }
}

void lag_contact_friction(const SpringModel& model, const std::vector<Obstacle>& obstacles,
                          const Eigen::MatrixXd* lagged_impulse,
                          const Eigen::VectorXd& first_iterate,
                          const Eigen::VectorXd& gradient_without_contacts, double time_step_s,
                          std::vector<ContactPlane>& planes) {
  const bool lagged = lagged_impulse != nullptr &&
                      lagged_impulse->rows() == static_cast<Eigen::Index>(obstacles.size()) &&
                      lagged_impulse->cols() == model.particle_count();
  const double inverse_h2 = 1.0 / (time_step_s * time_step_s);
  for (ContactPlane& plane : planes) {
    plane.slip_scale_m = friction_slip_speed_m_per_s * time_step_s;
    const int p = plane.particle;
    double normal_force_n = 0.0;
    if (lagged) {  // lambda = m J / h
      normal_force_n = model.mass[p] * (*lagged_impulse)(plane.obstacle, p) / time_step_s;
    } else {  // lambda = (m / h^2) depth(x_0 - (h^2 / m) g) = (m / h^2) (point - x_0) . n + g . n
      const double depth_m = (plane.point - first_iterate.segment<3>(3 * p)).dot(plane.normal);
      normal_force_n = model.mass[p] * inverse_h2 * depth_m +
                       gradient_without_contacts.segment<3>(3 * p).dot(plane.normal);
    }
    plane.friction_n = obstacles[plane.obstacle].kinetic_friction * std::max(0.0, normal_force_n);
  }
}

void remove_friction_given_in_step(const std::vector<ContactPlane>& planes,
                                   const Eigen::VectorXd& x, Eigen::MatrixXd& impulse_m_per_s) {
  for (const ContactPlane& plane : planes) {
    if (plane.friction_n > 0.0 && contact_slip_m(plane, x.segment<3>(3 * plane.particle)).norm() >
                                      sliding_slip_ratio * plane.slip_scale_m) {
      impulse_m_per_s(plane.obstacle, plane.particle) = 0.0;
    }
  }
}

double add_contact_potential(const std::vector<ContactPlane>& planes, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient) {
  double energy_j = 0.0;
  for (const ContactPlane& plane : planes) {
    const auto xp = x.segment<3>(3 * plane.particle);
    const double depth_m = contact_depth_m(plane, xp);
    if (depth_m > 0.0) {
      energy_j += 0.5 * plane.stiffness_n_per_m * depth_m * depth_m;
      if (gradient != nullptr) {
        gradient->segment<3>(3 * plane.particle) -=
            (plane.stiffness_n_per_m * depth_m) * plane.normal;
      }
    }
    if (plane.friction_n > 0.0) {
      const Eigen::Vector3d slip = contact_slip_m(plane, xp);
      const double y = slip.norm();
      const double e = plane.slip_scale_m;
      // f0 and f1(y) / y = f0'(y) / y (IPC's smoothed Coulomb friction, Li et al. 2020, eq. 15)
      const bool ramp = y < e;
      energy_j +=
          plane.friction_n * (ramp ? (-y * y * y / (3.0 * e * e) + y * y / e + e / 3.0) : y);
      if (gradient != nullptr) {
        const double force_per_slip = ramp ? (2.0 / e - y / (e * e)) : 1.0 / y;
        gradient->segment<3>(3 * plane.particle) += plane.friction_n * force_per_slip * slip;
      }
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
