#pragma once
/// \file
/// One time step of the mass-spring system.

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step_workspace.hpp"

namespace tissu {

enum class StepStatus {
  ok,
  non_finite,     ///< a position or velocity became NaN or infinite; the state is not usable
  not_converged,  ///< the step missed its integrator's tolerance (CG, Newton, L-BFGS, PD's check)
};

const char* to_string(StepStatus status);

/// The scenario name of an integrator ("implicit_euler", "projective_dynamics", ...).
const char* to_string(Integrator integrator);

/// The scenario name of a Projective Dynamics global solver ("direct", "colored_gauss_seidel",
/// ...).
const char* to_string(PdGlobalSolver solver);

/// The scenario name of a Newton preconditioner ("multigrid", "pd_matrix").
const char* to_string(NewtonPreconditioner preconditioner);

/// The scenario name of quasi-Newton's initial Hessian ("pd_matrix", "pd_multigrid").
const char* to_string(QuasiNewtonInitialHessian initial_hessian);

/// Advances `state` by params.time_step with the chosen integrator. Pinned particles keep their
/// velocity (zero unless prescribed). On non_finite the state is left as computed (the caller keeps
/// the last good state); the model is never modified.
StepStatus step(const SpringModel& model, const SolverParams& params, State& state);

/// Same as step(model, params, state), with the scratch buffers kept by the caller between steps:
/// no heap allocation once the sizes are known, except the few vectors of the implicit
/// integrator's conjugate gradient.
/// One workspace per concurrently stepped model. It adapts by itself when the model changes: every
/// cache in it is keyed on SpringModel::identity, so stepping a recompiled model (or another one)
/// with the same workspace gives the same result as a fresh workspace.
StepStatus step(const SpringModel& model, const SolverParams& params, State& state,
                StepWorkspace& workspace);

/// The iterations the last step made with `workspace`: conjugate-gradient iterations of
/// implicit_euler, local/global iterations of projective_dynamics, Newton iterations of newton,
/// L-BFGS iterations of quasi_newton (with the Newton iterations of its newton_fallback); 0 for
/// the explicit integrators.
int last_step_iterations(const SolverParams& params, const StepWorkspace& workspace);

}  // namespace tissu
