#include "solver/integrators/newton.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/forces/spring_coupling.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/integrators/step_minimisation.hpp"
#include "solver/parallel.hpp"
#include "solver/parallel_sum.hpp"

namespace tissu {
namespace {

constexpr double max_forcing_term = 0.25;  // loosest relative residual of a linear solve

void check_options(const NewtonOptions& options) {
  if (!(options.tolerance > 0.0) || options.max_iterations < 1 || options.cg_max_iterations < 1 ||
      !(options.gradient_reduction >= 0.0 && options.gradient_reduction <= 1.0)) {
    throw std::invalid_argument(
        "newton_step: expected newton.tolerance > 0, newton.max_iterations >= 1, "
        "newton.cg_max_iterations >= 1 and newton.gradient_reduction in [0, 1]");
  }
}

// a contact plane's friction F f0(|u|), u = P (x - start), has the Hessian (positive semidefinite)
// F/e^2 ((2e - y) P - y u^ u^T) while the slip y = |u| is below e, F/y (P - u^ u^T) beyond
Eigen::Matrix3d friction_hessian(const ContactPlane& plane, const Eigen::Vector3d& x) {
  const Eigen::Matrix3d tangential =
      Eigen::Matrix3d::Identity() - plane.normal * plane.normal.transpose();
  const Eigen::Vector3d slip = contact_slip_m(plane, x);
  const double y = slip.norm();
  const double e = plane.slip_scale_m;
  const Eigen::Matrix3d along =
      y > 0.0 ? Eigen::Matrix3d(slip * slip.transpose() / (y * y)) : Eigen::Matrix3d::Zero();
  if (y < e) return plane.friction_n / (e * e) * ((2.0 * e - y) * tangential - y * along);
  return plane.friction_n / y * (tangential - along);
}

// a contact plane's penalty, where it acts, adds k n n^T to its particle's diagonal block, and its
// friction its Hessian
void add_contact_hessian(const std::vector<ContactPlane>& contacts, const Eigen::VectorXd& x,
                         bool coupled, NewtonWorkspace& newton) {
  for (const ContactPlane& plane : contacts) {
    const Eigen::Vector3d xp = x.segment<3>(3 * plane.particle);
    const double depth_m = contact_depth_m(plane, xp);
    if (depth_m == 0.0 && plane.friction_n == 0.0) continue;
    Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
    if (depth_m > 0.0) block += plane.stiffness_n_per_m * plane.normal * plane.normal.transpose();
    if (plane.friction_n > 0.0) block += friction_hessian(plane, xp);
    newton.hessian.block(newton.hessian.diagonal[plane.particle]) += upper_triangle(block);
    if (coupled) {
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          newton.coupled_hessian.coeffRef(3 * plane.particle + r, 3 * plane.particle + c) +=
              block(r, c);
        }
      }
    }
  }
}

// H = M (1/h^2 + c/h) + sum of the springs' positive semidefinite blocks + the couplings' terms
// + the acting contact penalties' blocks
void assemble_hessian(const SpringModel& model, const StepPotential& potential,
                      const Eigen::VectorXd& x, const StepPotentialWorkspace& evaluated,
                      NewtonWorkspace& newton) {
  const int springs = model.spring_count();
  const double h = potential.time_step_s;
  const Eigen::Matrix3Xd& start_directions = evaluated.start_directions;
  const bool coupled = model.couplings.rows() > 0;
  const double viscous_scale = 1.0 / h;  // nu/h (N/m per N s/m)
  newton.spring_blocks.resize(springs);
  if (coupled) newton.coupled_spring_blocks.resize(springs);
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const auto xi = x.segment<3>(3 * model.springs(s, 0));
    const auto xj = x.segment<3>(3 * model.springs(s, 1));
    SymmetricBlock block =
        spring_hessian_block(xi - xj, model.stiffness[s], model.rest_length[s],
                             start_directions.col(s), viscous_scale * model.damping[s]);
    if (coupled) {  // evaluate_step_potential() left the couplings' tensions at x
      block -=
          upper_triangle(coupling_tension_jacobian(xi, xj, evaluated.coupling_tension[s], true));
      newton.coupled_spring_blocks[s] = full_block(block);
    }
    newton.spring_blocks[s] = block;
  }
  newton.diagonal = (1.0 / (h * h) + potential.air_damping / h) * model.mass;
  update_spring_block_pattern(model, newton.pattern);
  assemble_symmetric_spring_block_matrix(model, newton.pattern, newton.spring_blocks,
                                         newton.diagonal, true, newton.hessian);
  if (coupled) {
    assemble_spring_block_matrix(model, newton.pattern, newton.coupled_spring_blocks,
                                 newton.diagonal, true, newton.coupled_hessian);
    add_coupling_jacobian_blocks(model, newton.pattern, x, -1.0, true, newton.coupled_hessian);
  }
  if (potential.contacts != nullptr) add_contact_hessian(*potential.contacts, x, coupled, newton);
}

// preconditioned = an approximation of H^-1 residual (zero on pinned particles)
void precondition(NewtonPreconditioner preconditioner, MinimisationWorkspace& common,
                  NewtonWorkspace& newton) {
  if (preconditioner == NewtonPreconditioner::multigrid) {
    newton.multigrid.apply(newton.residual, common.preconditioned);
  } else {
    common.pd_matrix.solve(common.system, newton.residual, common.preconditioned);
  }
}

// correction ~ -H^-1 gradient by the preconditioned conjugate gradient from 0, to a residual of
// forcing_term |gradient| (gradient_n: |gradient|, N); returns the iterations. Stops at a direction
// of non-positive curvature (H is positive definite up to the couplings' cross terms), keeping what
// it has, or the preconditioned gradient if that is nothing yet.
int solve_newton_system(NewtonPreconditioner preconditioner, bool coupled,
                        MinimisationWorkspace& common, NewtonWorkspace& newton, double gradient_n,
                        double forcing_term, int max_iterations) {
  const Eigen::Index dofs = common.gradient.size();
  const int particles = static_cast<int>(dofs / 3);
  newton.correction.setZero(dofs);
  newton.residual = -common.gradient;
  precondition(preconditioner, common, newton);
  newton.search = common.preconditioned;
  double rz = particle_dot(newton.residual, common.preconditioned);
  const double target_n = forcing_term * gradient_n;
  double residual_n = gradient_n;  // the residual is -gradient
  int iteration = 0;
  while (iteration < max_iterations && residual_n > target_n) {
    if (coupled) {
      newton.hessian_search.noalias() = newton.coupled_hessian * newton.search;
    } else {
      symmetric_block_product(newton.hessian, newton.search, newton.hessian_search);
    }
    const double curvature = particle_dot(newton.search, newton.hessian_search);
    if (!(curvature > 0.0)) {
      if (iteration == 0) newton.correction = newton.search;
      break;
    }
    const double step = rz / curvature;
    // correction += step p, residual -= step H p, and |residual|, in one pass
    residual_n = std::sqrt(chunked_sum(particles, [&](int begin, int end) {
      const Eigen::Index start = 3 * begin, size = 3 * (end - begin);
      newton.correction.segment(start, size) += step * newton.search.segment(start, size);
      auto residual = newton.residual.segment(start, size);
      residual -= step * newton.hessian_search.segment(start, size);
      return residual.squaredNorm();
    }));
    precondition(preconditioner, common, newton);
    const double rz_next = particle_dot(newton.residual, common.preconditioned);
    const double beta = rz_next / rz;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
    for (int p = 0; p < particles; ++p) {
      newton.search.segment<3>(3 * p) =
          common.preconditioned.segment<3>(3 * p) + beta * newton.search.segment<3>(3 * p);
    }
    rz = rz_next;
    ++iteration;
  }
  return iteration;
}

}  // namespace

bool newton_iterations(const SpringModel& model, const NewtonOptions& options,
                       const StepPotential& potential, const Eigen::VectorXd& start_x,
                       double& energy_j, MinimisationWorkspace& common, NewtonWorkspace& newton) {
  check_options(options);
  const bool pd_preconditioner = options.preconditioner == NewtonPreconditioner::pd_matrix;
  const double force_scale_n = step_force_scale(model, potential);
  const double first_gradient_n = particle_norm(common.gradient);
  const double reduced_from_n =
      gradient_reduction_reference(first_gradient_n, options.tolerance, force_scale_n);

  newton.iterations = 0;
  newton.cg_iterations = 0;
  double gradient_n = first_gradient_n;  // |grad E| at common.x (N)
  bool converged = first_gradient_n == 0.0;
  while (!converged && newton.iterations < options.max_iterations) {
    assemble_hessian(model, potential, common.x, common.potential, newton);
    if (!pd_preconditioner) newton.multigrid.set_operator(newton.hessian, model.identity);
    const double forcing_term =
        std::min(max_forcing_term,
                 std::sqrt(relative_residual(gradient_n, force_scale_n, first_gradient_n)));
    newton.cg_iterations +=
        solve_newton_system(options.preconditioner, model.couplings.rows() > 0, common, newton,
                            gradient_n, forcing_term, options.cg_max_iterations);
    double trial_energy_j = energy_j;
    const double slope_j = particle_dot(common.gradient, newton.correction);
    if (!backtracking_line_search(model, potential, common.x, slope_j, energy_j, newton.correction,
                                  common.potential, common.trial_x, common.trial_gradient,
                                  trial_energy_j)) {
      break;  // no decrease along the Newton direction: round-off, or an indefinite coupling
    }
    ++newton.iterations;
    newton.correction_ratio =
        relative_correction(model, potential.time_step_s, newton.correction, common.trial_x,
                            start_x, common.external_force, 1.0);
    const double trial_gradient_n = particle_norm(common.trial_gradient);
    newton.gradient_ratio = trial_gradient_n / reduced_from_n;
    converged = minimiser_converged(newton.correction_ratio, options.tolerance,
                                    newton.gradient_ratio, options.gradient_reduction);
    common.x.swap(common.trial_x);
    common.gradient.swap(common.trial_gradient);
    gradient_n = trial_gradient_n;
    energy_j = trial_energy_j;
  }
  return converged;
}

StepStatus newton_step(const SpringModel& model, const SolverParams& params, State& state,
                       StepWorkspace& workspace) {
  const NewtonOptions& options = params.newton;
  check_options(options);
  NewtonWorkspace& newton = workspace.newton;

  StepPotential potential;
  double energy_j = 0.0;
  const bool pd_preconditioner = options.preconditioner == NewtonPreconditioner::pd_matrix;
  if (!start_step_minimisation(model, params, state, newton.common, &workspace.obstacle_distances,
                               lagged_penalty_impulse(model, workspace), potential, energy_j,
                               pd_preconditioner)) {
    return StepStatus::non_finite;
  }
  const bool converged =
      newton_iterations(model, options, potential, state.x, energy_j, newton.common, newton);
  return finish_step_minimisation(model, params.time_step, newton.common.x, converged, state);
}

}  // namespace tissu
