#pragma once
/// \file
/// What the minimisers of backward Euler's incremental potential (Newton, quasi-Newton) share:
/// the start of a step (its potential, first iterate and the PD matrix) and its end.

#include <Eigen/Core>

#include "solver/integrators/incremental_potential.hpp"
#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_system.hpp"
#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Buffers of one minimisation, sized on first use and reused. The PD matrix M/h^2 + L and its
/// factorisation (the preconditioner or initial Hessian of the minimisers) are rebuilt only when
/// the model (its identity) or h changes.
struct MinimisationWorkspace {
  PdSystem system;                   ///< M/h^2 + L, the Projective Dynamics matrix
  PdDirectSolver pd_matrix;          ///< its factorisation
  StepPotentialWorkspace potential;  ///< per-spring buffers of the potential
  Eigen::Matrix3Xd triangle_forces;  ///< 3 x #T aerodynamic scratch (N)
  Eigen::VectorXd external_force;    ///< 3#P gravity and wind at the start of the step (N)
  Eigen::VectorXd inertial;          ///< 3#P y = x_n + h v_n + h^2 f_ext / m (m)
  Eigen::VectorXd x;                 ///< 3#P the iterate (m)
  Eigen::VectorXd gradient;          ///< 3#P grad E at x (N)
  Eigen::VectorXd trial_x;           ///< 3#P the line search's point (m)
  Eigen::VectorXd trial_gradient;    ///< 3#P grad E there (N)
  Eigen::VectorXd preconditioned;    ///< 3#P (M/h^2 + L)^-1 q, zero on pinned particles (m)
};

/// Starts a step: f_ext (gravity and wind; air damping is left to the potential, implicit), y,
/// x = x_0 = x_n + h v_n, the PD matrix for this model and h, the potential's start directions,
/// and E(x_0) with its gradient. Fills `potential` (which points into `workspace` and `state`).
/// False when something is not finite (or the PD matrix cannot be factorised): the step is then
/// non_finite.
bool start_step_minimisation(const SpringModel& model, const SolverParams& params,
                             const State& state, MinimisationWorkspace& workspace,
                             StepPotential& potential, double& energy_j);

/// Ends a step at the iterate x (3#P, m): v = (x - x_n)/h for the free particles, then x. Pinned
/// particles keep their velocity (x holds their x_0).
void finish_step_minimisation(const SpringModel& model, double time_step_s,
                              const Eigen::VectorXd& x, State& state);

}  // namespace tissu
