#pragma once
/// \file
/// Scratch state of the quasi-Newton integrator, kept between steps by the caller.

#include <Eigen/Core>
#include <vector>

#include "solver/integrators/incremental_potential.hpp"
#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_system.hpp"

namespace tissu {

/// Buffers of quasi_newton_step(); sized on first use, reused afterwards. The initial Hessian
/// M/h^2 + L and its factorisation are rebuilt only when the model (its identity) or h changes.
struct QuasiNewtonWorkspace {
  PdSystem system;                   ///< M/h^2 + L, the Projective Dynamics matrix
  PdDirectSolver initial_hessian;    ///< its factorisation, applied as H_0^-1
  StepPotentialWorkspace potential;  ///< per-spring buffers of the potential
  Eigen::Matrix3Xd triangle_forces;  ///< 3 x #T aerodynamic scratch (N)
  Eigen::VectorXd external_force;    ///< 3#P gravity and wind at the start of the step (N)
  Eigen::VectorXd inertial;          ///< 3#P y = x_n + h v_n + h^2 f_ext / m (m)
  Eigen::VectorXd x;                 ///< 3#P the iterate (m)
  Eigen::VectorXd gradient;          ///< 3#P grad E at x (N)
  Eigen::VectorXd trial_x;           ///< 3#P the line search's point (m)
  Eigen::VectorXd trial_gradient;    ///< 3#P grad E there (N)
  Eigen::VectorXd direction;         ///< 3#P the search direction (m)
  Eigen::VectorXd preconditioned;    ///< 3#P H_0^-1 q, zero on pinned particles (m)
  Eigen::MatrixXd position_changes;  ///< 3#P x history: s_k = x_{k+1} - x_k (m)
  Eigen::MatrixXd gradient_changes;  ///< 3#P x history: t_k = g_{k+1} - g_k (N)
  std::vector<double> curvature;     ///< history: 1 / (s_k . t_k) (1/J)
  std::vector<double> coefficient;   ///< history: two-loop scratch
  int stored_pairs = 0;              ///< pairs in the history, the newest at (newest_pair)
  int newest_pair = -1;
  int iterations = 0;             ///< iterations of the last step
  double correction_ratio = 0.0;  ///< last max |dx_i| / max |x_i - x_n,i| (dimensionless)
};

}  // namespace tissu
