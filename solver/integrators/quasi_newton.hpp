#pragma once
/// \file
/// Backward Euler by a quasi-Newton minimisation of its incremental potential, with the
/// Projective Dynamics matrix as the initial Hessian (Liu, Bouaziz & Kavan 2017, "Quasi-Newton
/// methods for real-time simulation of hyperelastic materials").

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"
#include "solver/step_workspace.hpp"

namespace tissu {

/// One backward-Euler step: minimises the incremental potential E (incremental_potential.hpp:
/// springs, their couplings and their damping, air damping implicit, gravity and wind at the start
/// of the step) by L-BFGS (Nocedal & Wright 2006, Algorithm 7.4) from x_0 = x_n + h v_n:
/// - the two-loop recursion over the last params.quasi_newton.history pairs (lbfgs_history.hpp),
///   its initial inverse Hessian H_0^-1 = (M/h^2 + L)^-1, the PD matrix (Liu et al. 2017: far
///   closer to the Hessian of stiff springs than a scaled identity, constant per model and h,
///   prefactorised once);
/// - a backtracking line search on E (Armijo, c = 1e-4), falling back on the H_0 direction when
///   the history gives none;
/// - stops when the last quasi-Newton correction, relative to the step's displacement
///   (relative_correction()), is at most params.quasi_newton.tolerance, or after
///   params.quasi_newton.max_iterations;
/// - a step L-BFGS has not converged by then is finished by newton_iterations() from its last
///   iterate (params.quasi_newton.newton_fallback; the Newton options of params.newton with
///   quasi_newton's tolerance and the multigrid preconditioner): the true, clamped Hessian
///   converges the rare steps on which L-BFGS crawls (a cloth's release from rest, a light
///   garment settling on a body; docs/benchmarks.md).
/// Then v = (x - x_n)/h. Pinned particles move at their prescribed velocity. The same result for
/// any number of OpenMP threads. Returns not_converged when the tolerance was not met (the state
/// is advanced with the last iterate), non_finite on a non-finite prediction or potential.
/// Throws std::invalid_argument on options out of range. Does not advance state.time.
StepStatus quasi_newton_step(const SpringModel& model, const SolverParams& params, State& state,
                             StepWorkspace& workspace);

}  // namespace tissu
