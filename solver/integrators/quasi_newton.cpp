#include "solver/integrators/quasi_newton.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/forces/external_forces.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

void check_options(const QuasiNewtonOptions& options) {
  if (!(options.tolerance > 0.0) || options.max_iterations < 1 || options.history < 0) {
    throw std::invalid_argument(
        "quasi_newton_step: expected quasi_newton.tolerance > 0, quasi_newton.max_iterations >= 1 "
        "and quasi_newton.history >= 0");
  }
}

void clear_history(QuasiNewtonWorkspace& qn) {
  qn.stored_pairs = 0;
  qn.newest_pair = -1;
}

void resize_history(int dofs, int history, QuasiNewtonWorkspace& qn) {
  if (qn.position_changes.rows() != dofs || qn.position_changes.cols() != history) {
    qn.position_changes.resize(dofs, history);
    qn.gradient_changes.resize(dofs, history);
    qn.curvature.assign(history, 0.0);
    qn.coefficient.assign(history, 0.0);
  }
  qn.preconditioned.setZero(dofs);  // its pinned entries stay 0 for this model
  clear_history(qn);
}

// preconditioned = H_0^-1 q, the PD matrix on the free particles (pinned rows stay zero)
void apply_initial_inverse_hessian(const Eigen::VectorXd& q, QuasiNewtonWorkspace& qn) {
  qn.initial_hessian.solve(qn.system, q, qn.preconditioned);
}

// direction = -H^-1 gradient by the L-BFGS two-loop recursion
void lbfgs_direction(QuasiNewtonWorkspace& qn) {
  const int capacity = static_cast<int>(qn.curvature.size());
  qn.direction = qn.gradient;  // q
  for (int n = 0, k = qn.newest_pair; n < qn.stored_pairs; ++n, k = (k + capacity - 1) % capacity) {
    qn.coefficient[k] = qn.curvature[k] * qn.position_changes.col(k).dot(qn.direction);
    qn.direction -= qn.coefficient[k] * qn.gradient_changes.col(k);
  }
  apply_initial_inverse_hessian(qn.direction, qn);
  qn.direction = qn.preconditioned;  // r
  const int oldest = (qn.newest_pair - qn.stored_pairs + 1 + capacity) % std::max(capacity, 1);
  for (int n = 0, k = oldest; n < qn.stored_pairs; ++n, k = (k + 1) % capacity) {
    const double beta = qn.curvature[k] * qn.gradient_changes.col(k).dot(qn.direction);
    qn.direction += (qn.coefficient[k] - beta) * qn.position_changes.col(k);
  }
  qn.direction = -qn.direction;
}

// keeps (s, t) = (trial_x - x, trial_gradient - gradient) when s . t > 0 (the curvature condition
// that keeps the L-BFGS matrix positive definite; otherwise the pair is skipped)
void remember_pair(QuasiNewtonWorkspace& qn) {
  const int capacity = static_cast<int>(qn.curvature.size());
  if (capacity == 0) return;
  const int slot = (qn.newest_pair + 1) % capacity;
  qn.position_changes.col(slot) = qn.trial_x - qn.x;
  qn.gradient_changes.col(slot) = qn.trial_gradient - qn.gradient;
  const double curvature_j = qn.position_changes.col(slot).dot(qn.gradient_changes.col(slot));
  if (!(curvature_j > 0.0)) return;
  qn.curvature[slot] = 1.0 / curvature_j;
  qn.newest_pair = slot;
  qn.stored_pairs = std::min(qn.stored_pairs + 1, capacity);
}

}  // namespace

StepStatus quasi_newton_step(const SpringModel& model, const SolverParams& params, State& state,
                             StepWorkspace& workspace) {
  const QuasiNewtonOptions& options = params.quasi_newton;
  check_options(options);
  const double h = params.time_step;
  const int particles = model.particle_count();
  QuasiNewtonWorkspace& qn = workspace.quasi_newton;

  Environment explicit_forces = params.environment;
  explicit_forces.air_damping = 0.0;  // air damping is in the potential, implicit
  accumulate_external_forces(model, explicit_forces, state.time, state.x, state.v,
                             qn.triangle_forces, qn.external_force);
  predict_step(model, h, state, qn.external_force, qn.x, qn.inertial);
  if (!qn.inertial.allFinite()) return StepStatus::non_finite;
  update_pd_system(model, h, qn.system);
  if (!qn.initial_hessian.factorize(qn.system)) return StepStatus::non_finite;
  resize_history(3 * particles, options.history, qn);

  StepPotential potential;
  potential.time_step_s = h;
  potential.start_x = &state.x;
  potential.inertial = &qn.inertial;
  potential.air_damping = params.environment.air_damping;
  prepare_step_potential(model, potential, qn.potential);
  double energy_j = evaluate_step_potential(model, potential, qn.x, qn.potential, &qn.gradient);
  if (!std::isfinite(energy_j) || !qn.gradient.allFinite()) return StepStatus::non_finite;
  const double first_gradient_n = qn.gradient.norm();

  qn.iterations = 0;
  qn.correction_ratio = 0.0;
  bool converged = first_gradient_n == 0.0;
  while (!converged && qn.iterations < options.max_iterations) {
    lbfgs_direction(qn);
    if (!(qn.gradient.dot(qn.direction) < 0.0)) {  // not a descent direction: restart from H_0
      clear_history(qn);
      lbfgs_direction(qn);
    }
    double trial_energy_j = energy_j;
    if (!backtracking_line_search(model, potential, qn.x, qn.gradient, energy_j, qn.direction,
                                  qn.potential, qn.trial_x, qn.trial_gradient, trial_energy_j)) {
      if (qn.stored_pairs == 0) break;  // not even H_0's direction descends: round-off
      clear_history(qn);
      continue;
    }
    ++qn.iterations;
    qn.correction_ratio =
        relative_correction(model, h, qn.direction, qn.trial_x, state.x, qn.external_force, 1.0);
    converged = qn.correction_ratio <= options.tolerance;
    remember_pair(qn);
    qn.x.swap(qn.trial_x);
    qn.gradient.swap(qn.trial_gradient);
    energy_j = trial_energy_j;
  }
  if (!qn.x.allFinite()) return StepStatus::non_finite;

  const double inverse_h = 1.0 / h;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.inverse_mass[p] != 0.0) {
      state.v.segment<3>(3 * p) = inverse_h * (qn.x.segment<3>(3 * p) - state.x.segment<3>(3 * p));
    }
    state.x.segment<3>(3 * p) = qn.x.segment<3>(3 * p);
  }
  return converged ? StepStatus::ok : StepStatus::not_converged;
}

}  // namespace tissu
