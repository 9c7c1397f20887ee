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
  clear_history(qn);
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

// v = a w + (replace ? 0 : v), then u . v (0 without u): one pass over the vectors (3#P each),
// chunked so that the dot product has the same bits on any number of threads
double axpy_then_dot(double a, const double* w, bool replace, Eigen::VectorXd& v, const double* u) {
  return chunked_sum(static_cast<int>(v.size() / 3), [&](int begin, int end) {
    const Eigen::Index start = 3 * begin, size = 3 * (end - begin);
    auto v_chunk = v.segment(start, size);
    const Eigen::Map<const Eigen::VectorXd> w_chunk(w + start, size);
    if (replace) {
      v_chunk = a * w_chunk;
    } else {
      v_chunk += a * w_chunk;
    }
    return u == nullptr ? 0.0 : Eigen::Map<const Eigen::VectorXd>(u + start, size).dot(v_chunk);
  });
}

// direction = -H^-1 gradient by the L-BFGS two-loop recursion (Nocedal & Wright 2006, algorithm
// 7.4), run on q = -gradient so that it ends on the direction itself. Each pair's update and the
// next pair's dot product share one pass over the vectors: history + 1 passes a loop, not 2
// history. Returns gradient . direction (J, < 0 for a descent direction), from the last pass.
double lbfgs_direction(const SpringModel& model, QuasiNewtonInitialHessian kind,
                       QuasiNewtonWorkspace& qn) {
  const int capacity = static_cast<int>(qn.curvature.size());
  const int pairs = qn.stored_pairs;
  const auto s = [&](int k) { return qn.position_changes.col(k).data(); };
  const auto t = [&](int k) { return qn.gradient_changes.col(k).data(); };
  const double* gradient = qn.common.gradient.data();
  qn.direction.resize(qn.common.gradient.size());
  // newest pair first: alpha_k = rho_k s_k . q, q -= alpha_k t_k
  int k = qn.newest_pair;
  double dot = axpy_then_dot(-1.0, gradient, true, qn.direction, pairs > 0 ? s(k) : nullptr);
  for (int n = 0; n < pairs; ++n) {
    qn.coefficient[k] = qn.curvature[k] * dot;
    const int older = (k + capacity - 1) % capacity;
    dot = axpy_then_dot(-qn.coefficient[k], t(k), false, qn.direction,
                        n + 1 < pairs ? s(older) : nullptr);
    k = older;
  }
  apply_initial_inverse_hessian(model, kind, qn.direction, qn);  // r = H_0 q
  // oldest pair first: beta = rho_k t_k . r, r += (alpha_k - beta) s_k
  k = (qn.newest_pair - pairs + 1 + capacity) % std::max(capacity, 1);
  dot = axpy_then_dot(1.0, qn.common.preconditioned.data(), true, qn.direction,
                      pairs > 0 ? t(k) : gradient);
  for (int n = 0; n < pairs; ++n) {
    const double beta = qn.curvature[k] * dot;
    const int newer = (k + 1) % capacity;
    dot = axpy_then_dot(qn.coefficient[k] - beta, s(k), false, qn.direction,
                        n + 1 < pairs ? t(newer) : gradient);
    k = newer;
  }
  return dot;
}

// keeps (s, t) = (trial_x - x, trial_gradient - gradient) when s . t > 0 (the curvature condition
// that keeps the L-BFGS matrix positive definite; otherwise the pair is skipped)
void remember_pair(QuasiNewtonWorkspace& qn) {
  const int capacity = static_cast<int>(qn.curvature.size());
  if (capacity == 0) return;
  const int slot = (qn.newest_pair + 1) % capacity;
  const MinimisationWorkspace& common = qn.common;
  auto s = qn.position_changes.col(slot);
  auto t = qn.gradient_changes.col(slot);
  const double curvature_j = chunked_sum(static_cast<int>(s.size() / 3), [&](int begin, int end) {
    const Eigen::Index start = 3 * begin, size = 3 * (end - begin);
    auto s_chunk = s.segment(start, size);
    auto t_chunk = t.segment(start, size);
    s_chunk = common.trial_x.segment(start, size) - common.x.segment(start, size);
    t_chunk = common.trial_gradient.segment(start, size) - common.gradient.segment(start, size);
    return s_chunk.dot(t_chunk);
  });
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
  resize_history(3 * particles, options.history, qn);
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
      clear_history(qn);
      slope_j = lbfgs_direction(model, options.initial_hessian, qn);
    }
    double trial_energy_j = energy_j;
    if (!backtracking_line_search(model, potential, qn.common.x, slope_j, energy_j, qn.direction,
                                  qn.common.potential, qn.common.trial_x, qn.common.trial_gradient,
                                  trial_energy_j)) {
      if (qn.stored_pairs == 0) break;  // not even H_0's direction descends: round-off
      clear_history(qn);
      continue;
    }
    ++qn.iterations;
    qn.correction_ratio = relative_correction(model, h, qn.direction, qn.common.trial_x, state.x,
                                              qn.common.external_force, 1.0);
    qn.gradient_ratio = particle_norm(qn.common.trial_gradient) / reduced_from_n;
    converged = minimiser_converged(qn.correction_ratio, options.tolerance, qn.gradient_ratio,
                                    options.gradient_reduction);
    remember_pair(qn);
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
