#pragma once
/// \file
/// Scratch state of the Projective Dynamics integrator, kept between steps by the caller.

#include <Eigen/Core>

#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_iterative_solvers.hpp"
#include "solver/pd/pd_system.hpp"

namespace tissu {

/// Buffers of projective_dynamics_step(); sized on first use, reused afterwards. The global
/// system, its colouring and its factorisation are cached and rebuilt only when the model or the
/// time step changes (see update_pd_system()).
struct ProjectiveDynamicsWorkspace {
  PdSystem system;                   ///< constant part of the global step
  PdDirectSolver direct;             ///< factorisation for PdGlobalSolver::direct
  PdIterativeState iterative;        ///< buffers of the iterative global solvers
  Eigen::Matrix3Xd triangle_forces;  ///< 3 x #T aerodynamic scratch (N)
  Eigen::VectorXd external_force;    ///< 3#P f_ext at the start of the step (N)
  Eigen::VectorXd inertial;          ///< 3#P y = x + h v + h^2 M^-1 f_ext (m)
  Eigen::VectorXd positions;         ///< 3#P the iterate p (m)
  Eigen::VectorXd last_positions;    ///< 3#P p before the last iteration, for the tolerance (m)
  Eigen::Matrix3Xd projections;      ///< 3 x #S local step d_s = l_s (p_i - p_j)/|p_i - p_j| (m)
  Eigen::VectorXd rhs;               ///< 3#P c = M/h^2 y + J d (kg m/s^2)
  int iterations = 0;                ///< local/global iterations done by the last step
  Eigen::VectorXd correction;        ///< 3#P exact solution of the last global step minus p (m)
  double estimated_error = 0.0;      ///< the last step's estimated error (0 if not checked)
};

}  // namespace tissu
