#include "solver/forces/accumulate_forces.hpp"

#include <cassert>

#include "solver/forces/aerodynamic_force.hpp"
#include "solver/forces/spring_coupling.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/parallel.hpp"

namespace tissu {

void accumulate_forces(const SpringModel& model, const Environment& environment, double time_s,
                       const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                       ForceWorkspace& workspace, Eigen::VectorXd& force) {
  const int particles = model.particle_count();
  const int springs = model.spring_count();
  assert(x.size() == 3 * particles && v.size() == 3 * particles);
  assert(model.incidence.offsets.size() == static_cast<std::size_t>(particles) + 1 &&
         "call finalize_model() first");
  workspace.spring_forces.resize(3, springs);
  force.resize(3 * particles);
  const bool coupled = model.couplings.rows() > 0;
  if (coupled) {
    spring_coupling_tensions(model, x, workspace.spring_stretch, workspace.coupling_tension);
  }

#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const int i = model.springs(s, 0);
    const int j = model.springs(s, 1);
    const auto xi = x.segment<3>(3 * i);
    const auto xj = x.segment<3>(3 * j);
    workspace.spring_forces.col(s) =
        spring_force(xi, xj, model.stiffness[s], model.rest_length[s]) +
        spring_damping_force(xi, xj, v.segment<3>(3 * i), v.segment<3>(3 * j), model.damping[s]);
    if (coupled) {  // the couplings' tension T: -T u on i
      const double length_m = (xi - xj).norm();
      if (length_m >= spring_length_epsilon) {
        workspace.spring_forces.col(s) -= workspace.coupling_tension[s] / length_m * (xi - xj);
      }
    }
  }

  const ParticleSpringIncidence& incidence = model.incidence;
  const Eigen::Vector3d gravity = environment.gravity;
  const double air_damping = environment.air_damping;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    Eigen::Vector3d f = model.mass[p] * (gravity - air_damping * v.segment<3>(3 * p));
    for (int e = incidence.offsets[p]; e < incidence.offsets[p + 1]; ++e) {
      const auto spring = workspace.spring_forces.col(incidence.springs[e]);
      if (incidence.first_end[e]) {
        f += spring;
      } else {
        f -= spring;
      }
    }
    force.segment<3>(3 * p) = f;
  }

  add_aerodynamic_forces(model, environment.wind, time_s, x, v, workspace.triangle_forces, force);
}

}  // namespace tissu
