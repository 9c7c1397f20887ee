#pragma once
/// \file
/// Projective Dynamics for mass-spring systems: backward Euler by alternating local and global
/// steps (Liu et al. 2013, "Fast simulation of mass-spring systems"; Bouaziz et al. 2014,
/// "Projective dynamics"; course, Algorithms 1-3).

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"
#include "solver/step_workspace.hpp"

namespace tissu {

/// One backward-Euler step minimising
///   1/(2h^2) |p - y|_M^2 + sum over springs of s/2 |p_i - p_j - d_ij|^2
/// over the new positions p and the spring directions d_ij (|d_ij| = l_ij), with the inertial
/// prediction y = x + h v + h^2 M^-1 f_ext and f_ext = gravity, air damping and wind evaluated at
/// the start of the step (accumulate_external_forces(); the course's Verlet prediction, Algorithm
/// 2, in velocity form). Starting from p = x + h v, params.pd.iterations times:
/// - local step (Algorithm 3), per spring in parallel: d_ij = l_ij (p_i - p_j) / |p_i - p_j|
///   (direction of x_i - x_j, or zero, for a spring of length below spring_length_epsilon);
/// - global step: (M/h^2 + L) p = M/h^2 y + J d, L the stiffness-weighted spring Laplacian (x, y,
///   z alike), solved by params.pd.global_solver: exactly (direct, cached LDL^T) or by
///   params.pd.linear_iterations sweeps (Jacobi, Chebyshev, Gauss-Seidel, coloured Gauss-Seidel).
/// Then v = (p - x)/h, x = p. Pinned particles are eliminated: p_i = x_i + h v_i with their
/// prescribed (kept) velocity, moved to the right-hand side of their neighbours.
/// - At convergence this is the exact backward-Euler step of the springs (the energy converges
///   monotonically with the direct solver; Liu et al. 2013), which implicit_euler_step()
///   approximates by one Newton iteration.
/// - Spring damping (model.damping) is NOT applied: a viscous spring force along u = (p_i - p_j)
///   / |p_i - p_j| is not of the (L kron I3) form the constant global matrix needs, and explicit it
///   would be unstable at PD's time steps. Damping comes from environment.air_damping (explicit, in
///   f_ext, stable for h c < 2; the course's f_damping) and from backward Euler's own numerical
///   dissipation.
/// - A cloth at rest in equilibrium (spring forces + f_ext = 0) is a fixed point of every local
///   and every global iteration (p starts at x + h v = x), whatever their number: it stays at
///   rest to round-off, and PD with few iterations still settles on the true equilibrium.
/// - Results are independent of the number of OpenMP threads for every global solver.
/// - Spring couplings (model.couplings) have no projection: a model with any is refused.
/// Throws std::invalid_argument on options out of range (see ProjectiveDynamicsOptions) or on a
/// model with couplings.
/// - With an iterative global solver, the step is checked after its iterations
///   (ProjectiveDynamicsOptions::max_estimated_error): one exact solve of the last global step,
///   with the factorisation the direct solver uses, tells how much error the sweeps left.
/// Returns non_finite if the prediction is not finite (state unchanged), not_converged if
/// params.pd.tolerance > 0 was not met within params.pd.iterations or the check failed (state
/// advanced anyway).
/// Does not advance state.time (step() does).
StepStatus projective_dynamics_step(const SpringModel& model, const SolverParams& params,
                                    State& state, StepWorkspace& workspace);

/// Local step alone, for tests and benchmarks: d_s (3 x #S, m) from positions p (3#P, m), falling
/// back on the direction of x (3#P, m) for a collapsed spring. Parallel over springs.
void pd_local_step(const SpringModel& model, const Eigen::VectorXd& p, const Eigen::VectorXd& x,
                   Eigen::Matrix3Xd& projections);

/// Right-hand side of the global step, c_i = m_i/h^2 y_i + sum over springs s of i of
/// +-s_s d_s (+ when i is springs(s, 0)), for every particle (3#P, kg m/s^2), from y (3#P, m)
/// and d (3 x #S, m). Parallel over particles in model.incidence order.
void pd_global_rhs(const SpringModel& model, const PdSystem& system, const Eigen::VectorXd& y,
                   const Eigen::Matrix3Xd& projections, Eigen::VectorXd& rhs);

}  // namespace tissu
