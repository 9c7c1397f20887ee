#pragma once
/// \file
/// Backward Euler by Newton's method on its incremental potential, each linear solve by a
/// conjugate gradient preconditioned with aggregation multigrid on the Hessian (or with the
/// prefactorised Projective Dynamics matrix).

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"
#include "solver/step_workspace.hpp"

namespace tissu {

/// One backward-Euler step: minimises the incremental potential E (incremental_potential.hpp:
/// springs, their couplings and their damping, air damping implicit, gravity and wind at the start
/// of the step) by Newton's method from x_0 = x_n + h v_n (Gast et al. 2015; Li et al. 2020's
/// projected Newton):
/// - the Hessian with every spring's block made positive semidefinite: the clamped elastic block
///   (spring_force_jacobian_clamped: compressed springs lose their negative transverse term) plus
///   nu/h u_n u_n^T, and the couplings' terms;
/// - H dx = -grad E solved inexactly by a conjugate gradient preconditioned with one V-cycle of
///   AggregationMultigrid on H (params.newton.preconditioner = multigrid: aggregates kept per
///   model, coarse operators rebuilt at every Newton iteration; on the springs' part of H when
///   the model has couplings), or with (M/h^2 + L)^-1, the PD
///   matrix (pd_matrix: constant per model and h, prefactorised once), to the relative residual
///   min(0.25, sqrt(|grad E| / F)) (Eisenstat & Walker 1996's forcing term; F the step's force
///   scale) or params.newton.cg_max_iterations; a direction of negative curvature ends it early;
/// - a backtracking line search on E (Armijo, c = 1e-4);
/// - stops when max_i |dx_i| <= params.newton.tolerance * max_i |x_i - x_n,i| (the last Newton
///   correction relative to the step's displacement, the measure of ProjectiveDynamicsOptions::
///   tolerance), or after params.newton.max_iterations.
/// Then v = (x - x_n)/h. Pinned particles move at their prescribed velocity. The same result for
/// any number of OpenMP threads. Returns not_converged when the tolerance was not met (the state
/// is advanced with the last iterate), non_finite on a non-finite prediction or potential.
/// Throws std::invalid_argument on options out of range. Does not advance state.time.
StepStatus newton_step(const SpringModel& model, const SolverParams& params, State& state,
                       StepWorkspace& workspace);

/// newton_step()'s iterations on a step whose potential start_step_minimisation() has prepared in
/// `common`, from the iterate common.x (common.gradient and energy_j, the potential, at it; both
/// updated), start_x the positions x_n at the step's start. Returns whether the tolerance was met.
/// Lets another minimiser finish a step it could not converge (quasi_newton.hpp); with
/// options.preconditioner = pd_matrix, common.pd_matrix must hold the PD matrix's factor.
bool newton_iterations(const SpringModel& model, const NewtonOptions& options,
                       const StepPotential& potential, const Eigen::VectorXd& start_x,
                       double& energy_j, MinimisationWorkspace& common, NewtonWorkspace& newton);

}  // namespace tissu
