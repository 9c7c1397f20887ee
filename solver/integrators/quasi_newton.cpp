#include "solver/integrators/quasi_newton.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/integrators/newton.hpp"
#include "solver/integrators/step_minimisation.hpp"
#include "solver/parallel_sum.hpp"

namespace tissu {
namespace {

void check_options(const QuasiNewtonOptions& options) {
  if (!(options.tolerance > 0.0) || options.max_iterations < 1 || options.history < 0 ||
      !(options.gradient_reduction >= 0.0 && options.gradient_reduction <= 1.0)) {
    throw std::invalid_argument(
        "quasi_newton_step: expected quasi_newton.tolerance > 0, quasi_newton.max_iterations >= 1, "
        "quasi_newton.history >= 0 and quasi_newton.gradient_reduction in [0, 1]");
  }
}

// by free particle, the stiffness of its planes' friction on its smoothed start, 2F/e (N/m; the
// friction's Hessian at no slip, contact_planes.hpp); empty when no plane has friction. On the
// V-cycle's operator it gives H_0 what holds a resting cloth's sliding modes, which the springs
// do not resist.
void friction_stiffness_by_free_particle(const std::vector<ContactPlane>& contacts,
                                         const PdSystem& system, Eigen::VectorXd& stiffness) {
  stiffness.resize(0);
  for (const ContactPlane& plane : contacts) {
    if (!(plane.friction_n > 0.0)) continue;
    if (stiffness.size() == 0) {
      stiffness.setZero(static_cast<Eigen::Index>(system.free_particles.size()));
    }
    stiffness[system.free_index[plane.particle]] += 2.0 * plane.friction_n / plane.slip_scale_m;
  }
}

// preconditioned = H_0^-1 q, the PD matrix on the free particles (pinned rows stay zero), solved
// by its factor or approximated by multigrid
void apply_initial_inverse_hessian(const SpringModel& model, QuasiNewtonInitialHessian kind,
                                   const Eigen::VectorXd& q, QuasiNewtonWorkspace& qn) {
  if (kind == QuasiNewtonInitialHessian::pd_multigrid) {
    qn.pd_multigrid.apply(model, qn.common.system, q, qn.common.preconditioned);
    return;
  }
  qn.common.pd_matrix.solve(qn.common.system, q, qn.common.preconditioned);
}

// direction = -H^-1 gradient, L-BFGS's from the PD matrix or its V-cycle as H_0
// (lbfgs_history.hpp); returns gradient . direction (J, < 0 for a descent direction)
double lbfgs_direction(const SpringModel& model, QuasiNewtonInitialHessian kind,
                       QuasiNewtonWorkspace& qn) {
  return qn.history.direction(
      qn.common.gradient,
      [&](const Eigen::VectorXd& q) -> const Eigen::VectorXd& {
        apply_initial_inverse_hessian(model, kind, q, qn);
        return qn.common.preconditioned;
      },
      qn.direction);
}

}  // namespace

StepStatus quasi_newton_step(const SpringModel& model, const SolverParams& params, State& state,
                             StepWorkspace& workspace) {
  const QuasiNewtonOptions& options = params.quasi_newton;
  check_options(options);
  const double h = params.time_step;
  const int particles = model.particle_count();
  QuasiNewtonWorkspace& qn = workspace.quasi_newton;

  StepPotential potential;
  double energy_j = 0.0;
  const bool multigrid = options.initial_hessian == QuasiNewtonInitialHessian::pd_multigrid;
  if (!start_step_minimisation(model, params, state, qn.common, &workspace.obstacle_distances,
                               lagged_penalty_impulse(model, workspace), potential, energy_j,
                               !multigrid)) {
    return StepStatus::non_finite;
  }
  if (multigrid) {  // with the PD matrix's factor, start_step_minimisation() prepared it
    update_pd_system(model, h, qn.common.system);
    if (!qn.pd_multigrid.prepare(model, qn.common.system)) return StepStatus::non_finite;
    friction_stiffness_by_free_particle(qn.common.contacts, qn.common.system,
                                        qn.friction_stiffness);
    if (!qn.pd_multigrid.set_extra_diagonal(qn.friction_stiffness)) return StepStatus::non_finite;
  }
  qn.history.reset(3 * particles, options.history);
  const double first_gradient_n = particle_norm(qn.common.gradient);
  const double reduced_from_n = gradient_reduction_reference(first_gradient_n, options.tolerance,
                                                             step_force_scale(model, potential));

  qn.iterations = 0;
  qn.correction_ratio = 0.0;
  qn.gradient_ratio = 0.0;
  bool converged = first_gradient_n == 0.0;
  while (!converged && qn.iterations < options.max_iterations) {
    double slope_j = lbfgs_direction(model, options.initial_hessian, qn);
    if (!(slope_j < 0.0)) {  // not a descent direction: restart from H_0
      qn.history.clear();
      slope_j = lbfgs_direction(model, options.initial_hessian, qn);
    }
    double trial_energy_j = energy_j;
    if (!backtracking_line_search(model, potential, qn.common.x, slope_j, energy_j, qn.direction,
                                  qn.common.potential, qn.common.trial_x, qn.common.trial_gradient,
                                  trial_energy_j)) {
      if (qn.history.pairs() == 0) break;  // not even H_0's direction descends: round-off
      qn.history.clear();
      continue;
    }
    ++qn.iterations;
    qn.correction_ratio = relative_correction(model, h, qn.direction, qn.common.trial_x, state.x,
                                              qn.common.external_force, 1.0);
    qn.gradient_ratio = particle_norm(qn.common.trial_gradient) / reduced_from_n;
    converged = minimiser_converged(qn.correction_ratio, options.tolerance, qn.gradient_ratio,
                                    options.gradient_reduction);
    qn.history.remember(qn.common.x, qn.common.trial_x, qn.common.gradient,
                        qn.common.trial_gradient);
    qn.common.x.swap(qn.common.trial_x);
    qn.common.gradient.swap(qn.common.trial_gradient);
    energy_j = trial_energy_j;
  }
  qn.newton_iterations = 0;
  if (!converged && options.newton_fallback) {
    NewtonOptions newton = params.newton;
    newton.tolerance = options.tolerance;
    newton.gradient_reduction = options.gradient_reduction;
    newton.preconditioner = NewtonPreconditioner::multigrid;  // needs no factor
    converged =
        newton_iterations(model, newton, potential, state.x, energy_j, qn.common, workspace.newton);
    qn.newton_iterations = workspace.newton.iterations;
  }
  return finish_step_minimisation(model, h, qn.common.x, converged, state);
}

}  // namespace tissu
