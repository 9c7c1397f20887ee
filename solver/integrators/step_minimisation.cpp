#include "solver/integrators/step_minimisation.hpp"

#include <cmath>

#include "solver/forces/external_forces.hpp"
#include "solver/parallel.hpp"

namespace tissu {

bool start_step_minimisation(const SpringModel& model, const SolverParams& params,
                             const State& state, MinimisationWorkspace& workspace,
                             ObstacleDistanceCache* obstacle_distances,
                             const Eigen::MatrixXd* lagged_normal_impulse, StepPotential& potential,
                             double& energy_j, bool use_pd_matrix) {
  const double h = params.time_step;
  Environment explicit_forces = params.environment;
  explicit_forces.air_damping = 0.0;  // air damping is in the potential, implicit
  accumulate_external_forces(model, explicit_forces, state.time, state.x, state.v,
                             workspace.triangle_forces, workspace.external_force);
  predict_step(model, h, state, workspace.external_force, workspace.x, workspace.inertial);
  if (!workspace.inertial.allFinite()) return false;
  if (use_pd_matrix) {
    update_pd_system(model, h, workspace.system);
    // a preconditioner need not be exact: float sweeps, 3 to 28 % faster (docs/benchmarks.md)
    workspace.pd_matrix.set_precision(SolvePrecision::single);
    if (!workspace.pd_matrix.factorize(workspace.system)) return false;
  }
  workspace.preconditioned.setZero(3 * model.particle_count());  // pinned entries stay 0

  potential = StepPotential{};
  potential.time_step_s = h;
  potential.start_x = &state.x;
  potential.inertial = &workspace.inertial;
  potential.air_damping = params.environment.air_damping;
  if (obstacle_distances != nullptr && !params.obstacles.empty()) {
    obstacle_distances->prepare(model, params.obstacles);  // an integrator called on its own
  }
  find_contact_planes(model, params.obstacles, params.obstacle_penalty, h, state.time + h, state.x,
                      workspace.x, workspace.contacts, obstacle_distances);
  prepare_step_potential(model, potential, workspace.potential);
  // E(x_0) without the contacts, whose friction is estimated from that gradient, then with them
  energy_j = evaluate_step_potential(model, potential, workspace.x, workspace.potential,
                                     &workspace.gradient);
  if (!workspace.contacts.empty()) {
    if (params.friction_in_step) {
      lag_contact_friction(model, params.obstacles, lagged_normal_impulse, workspace.x,
                           workspace.gradient, h, workspace.contacts);
    }
    potential.contacts = &workspace.contacts;
    energy_j += add_contact_potential(workspace.contacts, workspace.x, &workspace.gradient);
  }
  return std::isfinite(energy_j) && workspace.gradient.allFinite();
}

StepStatus finish_step_minimisation(const SpringModel& model, double time_step_s,
                                    const Eigen::VectorXd& x, bool converged, State& state) {
  if (!x.allFinite()) return StepStatus::non_finite;
  const int particles = model.particle_count();
  const double inverse_h = 1.0 / time_step_s;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.inverse_mass[p] != 0.0) {
      state.v.segment<3>(3 * p) = inverse_h * (x.segment<3>(3 * p) - state.x.segment<3>(3 * p));
    }
    state.x.segment<3>(3 * p) = x.segment<3>(3 * p);
  }
  return converged ? StepStatus::ok : StepStatus::not_converged;
}

}  // namespace tissu
