#pragma once
/// \file
/// Scratch state of the Newton integrator, kept between steps by the caller.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "solver/forces/spring_block_matrix.hpp"
#include "solver/forces/symmetric_block_matrix.hpp"
#include "solver/integrators/minimisation_workspace.hpp"
#include "solver/multigrid/aggregation_multigrid.hpp"

namespace tissu {

/// Buffers of newton_step(); sized on first use, reused afterwards. The preconditioner (the PD
/// matrix, in `common`) and the Hessian's pattern are rebuilt only when the model (its identity)
/// or h changes. The Hessian is stored in symmetric 3x3 blocks; a model with couplings (whose cross
/// terms are not symmetric blocks) also keeps all of H in Eigen's row-major storage for the
/// conjugate gradient's products, the multigrid preconditioning it from the springs' part.
struct NewtonWorkspace {
  MinimisationWorkspace common;               ///< potential, iterate, PD matrix (preconditioner)
  SpringBlockPattern pattern;                 ///< sparsity of the Hessian
  std::vector<SymmetricBlock> spring_blocks;  ///< #S Hessian block of each spring (N/m)
  std::vector<Eigen::Matrix3d> coupled_spring_blocks;  ///< the same, full, with couplings only
  Eigen::VectorXd diagonal;                            ///< #P m_i (1/h^2 + c/h) (kg/s^2)
  SymmetricBlockMatrix hessian;  ///< 3#P x 3#P H without the couplings' cross terms (N/m)
  Eigen::SparseMatrix<double, Eigen::RowMajor> coupled_hessian;  ///< all of H, with couplings only
  AggregationMultigrid multigrid;
  Eigen::VectorXd correction;      ///< 3#P the Newton step dx, H dx = -grad E (m)
  Eigen::VectorXd residual;        ///< 3#P conjugate gradient residual (N)
  Eigen::VectorXd search;          ///< 3#P conjugate gradient direction (m)
  Eigen::VectorXd hessian_search;  ///< 3#P H search (N)
  int iterations = 0;              ///< Newton iterations of the last step
  int cg_iterations = 0;           ///< conjugate gradient iterations of the last step, in all
  double correction_ratio = 0.0;   ///< the last relative_correction() (dimensionless)
  double gradient_ratio = 0.0;     ///< the last gradient over what gradient_reduction scales
};

}  // namespace tissu
