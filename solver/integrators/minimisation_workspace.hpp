#pragma once
/// \file
/// Buffers that the minimisers of backward Euler's incremental potential (Newton, quasi-Newton)
/// share, kept between steps by the caller; filled by step_minimisation.hpp's functions.

#include <Eigen/Core>

#include <vector>

#include "solver/collision/contact_planes.hpp"
#include "solver/integrators/incremental_potential.hpp"
#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_system.hpp"

namespace tissu {

/// Buffers of one minimisation, sized on first use and reused. The PD matrix M/h^2 + L and its
/// factorisation (the preconditioner or initial Hessian of the minimisers) are rebuilt only when
/// the model (its identity) or h changes.
struct MinimisationWorkspace {
  PdSystem system;                     ///< M/h^2 + L, the Projective Dynamics matrix
  PdDirectSolver pd_matrix;            ///< its factorisation
  StepPotentialWorkspace potential;    ///< per-spring buffers of the potential
  Eigen::Matrix3Xd triangle_forces;    ///< 3 x #T aerodynamic scratch (N)
  Eigen::VectorXd external_force;      ///< 3#P gravity and wind at the start of the step (N)
  Eigen::VectorXd inertial;            ///< 3#P y = x_n + h v_n + h^2 f_ext / m (m)
  Eigen::VectorXd x;                   ///< 3#P the iterate (m)
  Eigen::VectorXd gradient;            ///< 3#P grad E at x (N)
  Eigen::VectorXd trial_x;             ///< 3#P the line search's point (m)
  Eigen::VectorXd trial_gradient;      ///< 3#P grad E there (N)
  Eigen::VectorXd preconditioned;      ///< 3#P (M/h^2 + L)^-1 q, zero on pinned particles (m)
  std::vector<ContactPlane> contacts;  ///< the step's obstacle contacts in its potential
};

}  // namespace tissu
