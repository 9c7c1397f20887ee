#include "solver/forces/external_forces.hpp"

#include <cassert>

#include "solver/forces/aerodynamic_force.hpp"
#include "solver/parallel.hpp"

namespace tissu {

void accumulate_external_forces(const SpringModel& model, const Environment& environment,
                                double time_s, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                Eigen::Matrix3Xd& triangle_forces, Eigen::VectorXd& force) {
  const int particles = model.particle_count();
  assert(x.size() == 3 * particles && v.size() == 3 * particles);
  force.resize(3 * particles);
  const Eigen::Vector3d gravity = environment.gravity;
  const double air_damping = environment.air_damping;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    force.segment<3>(3 * p) = model.mass[p] * (gravity - air_damping * v.segment<3>(3 * p));
  }
  add_aerodynamic_forces(model, environment.wind, time_s, x, v, triangle_forces, force);
}

}  // namespace tissu
