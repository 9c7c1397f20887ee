#pragma once
/// \file
/// Linearised implicit (backward) Euler integrator of Baraff & Witkin.

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"
#include "solver/step_workspace.hpp"

namespace tissu {

/// One step of linearised backward Euler (one Newton iteration), first order, unconditionally
/// stable for the springs:
///   (M - h df/dv - h^2 df/dx) Delta v = h (f0 + h df/dx v0),  v += Delta v,  x += h v,
/// with f0 = f(x0, v0, t) and the Jacobians of force_jacobian.hpp taken at x0. Source: Baraff &
/// Witkin 1998, "Large steps in cloth simulation" (their linearised step, multiplied by M to make
/// it symmetric).
/// - df/dx uses spring_force_jacobian_clamped(): the transverse term of compressed springs is
///   dropped so that A = M - h df/dv - h^2 df/dx is symmetric positive definite.
/// - Wind is explicit (in f0 only); spring and air damping are implicit through df/dv.
/// - Pinned particles (inverse_mass 0) by constraint filtering: with S = I on free and 0 on pinned
///   degrees of freedom, solve (S A S + (I - S)) Delta v = S b, the symmetric form of Baraff &
///   Witkin's filtered (modified) conjugate gradient; pinned particles keep their velocity.
/// - Solved by Eigen's ConjugateGradient (Lower|Upper, diagonal preconditioner), warm-started
///   from the previous Delta v, to params.implicit.cg_tolerance (relative residual).
/// Returns not_converged if the solve did not converge (the state is still advanced with the last
/// iterate), non_finite if the right-hand side is not finite (the state is left unchanged).
/// Does not advance state.time (step() does).
StepStatus implicit_euler_step(const SpringModel& model, const SolverParams& params, State& state,
                               StepWorkspace& workspace);

}  // namespace tissu
