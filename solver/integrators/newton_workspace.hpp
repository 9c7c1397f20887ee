#pragma once
/// \file
/// Scratch state of the Newton integrator, kept between steps by the caller.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "solver/forces/spring_block_matrix.hpp"
#include "solver/integrators/incremental_potential.hpp"
#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_system.hpp"

namespace tissu {

/// Buffers of newton_step(); sized on first use, reused afterwards. The preconditioner M/h^2 + L,
/// its factorisation and the Hessian's pattern are rebuilt only when the model (its identity) or
/// h changes. The Hessian is stored row-major so that its products run in parallel (symmetric:
/// the same data as column-major).
struct NewtonWorkspace {
  PdSystem system;                ///< M/h^2 + L, the Projective Dynamics matrix
  PdDirectSolver preconditioner;  ///< its factorisation, the conjugate gradient's preconditioner
  SpringBlockPattern pattern;     ///< sparsity of the Hessian
  std::vector<Eigen::Matrix3d> spring_blocks;            ///< #S Hessian block of each spring (N/m)
  Eigen::VectorXd diagonal;                              ///< #P m_i (1/h^2 + c/h) (kg/s^2)
  Eigen::SparseMatrix<double, Eigen::RowMajor> hessian;  ///< 3#P x 3#P (N/m)
  StepPotentialWorkspace potential;                      ///< per-spring buffers of the potential
  Eigen::Matrix3Xd triangle_forces;                      ///< 3 x #T aerodynamic scratch (N)
  Eigen::VectorXd external_force;  ///< 3#P gravity and wind at the start of the step (N)
  Eigen::VectorXd inertial;        ///< 3#P y = x_n + h v_n + h^2 f_ext / m (m)
  Eigen::VectorXd x;               ///< 3#P the iterate (m)
  Eigen::VectorXd gradient;        ///< 3#P grad E at x (N)
  Eigen::VectorXd trial_x;         ///< 3#P the line search's point (m)
  Eigen::VectorXd trial_gradient;  ///< 3#P grad E there (N)
  Eigen::VectorXd correction;      ///< 3#P the Newton step dx, H dx = -grad E (m)
  Eigen::VectorXd residual;        ///< 3#P conjugate gradient residual (N)
  Eigen::VectorXd preconditioned;  ///< 3#P P^-1 residual, zero on pinned particles (m)
  Eigen::VectorXd search;          ///< 3#P conjugate gradient direction (m)
  Eigen::VectorXd hessian_search;  ///< 3#P H search (N)
  int iterations = 0;              ///< Newton iterations of the last step
  int cg_iterations = 0;           ///< conjugate gradient iterations of the last step, in all
  double correction_ratio = 0.0;   ///< last max |dx_i| / max |x_i - x_n,i| (dimensionless)
};

}  // namespace tissu
