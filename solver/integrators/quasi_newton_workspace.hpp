#pragma once
/// \file
/// Scratch state of the quasi-Newton integrator, kept between steps by the caller.

#include <Eigen/Core>
#include <vector>

#include "solver/integrators/lbfgs_history.hpp"
#include "solver/integrators/minimisation_workspace.hpp"
#include "solver/multigrid/pd_multigrid.hpp"

namespace tissu {

/// Buffers of quasi_newton_step(); sized on first use, reused afterwards. The initial Hessian
/// (the PD matrix, in `common`) is rebuilt only when the model (its identity) or h changes.
struct QuasiNewtonWorkspace {
  MinimisationWorkspace common;        ///< potential, iterate, PD matrix (the initial Hessian)
  PdMultigrid pd_multigrid;            ///< the PD matrix's V-cycle, the other initial Hessian
  Eigen::VectorXd friction_stiffness;  ///< #F friction's stiffness added to it (N/m), or empty
  Eigen::VectorXd direction;           ///< 3#P the search direction (m)
  LbfgsHistory history;                ///< the last pairs s_k = x_{k+1} - x_k, t_k = g_{k+1} - g_k
  int iterations = 0;                  ///< L-BFGS iterations of the last step
  int newton_iterations = 0;           ///< Newton iterations that finished it (newton_fallback)
  double correction_ratio = 0.0;       ///< the last relative_correction() (dimensionless)
  /// |g| at the end of the last step / max(|g| at its start, tolerance F), F = step_force_scale()
  double gradient_ratio = 0.0;
};

}  // namespace tissu
