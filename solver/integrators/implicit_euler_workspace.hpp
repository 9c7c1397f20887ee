#pragma once
/// \file
/// Scratch state of the implicit Euler integrator, kept between steps by the caller.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "solver/forces/spring_block_matrix.hpp"

namespace tissu {

/// Buffers of implicit_euler_step(); sized on first use, reused afterwards, and the caches keyed on
/// the model's identity (matrix pattern, warm start) rebuilt when the model changes. The matrix is
/// stored row-major so that Eigen's conjugate gradient (Lower|Upper) multiplies it with OpenMP; it
/// is symmetric, so this is the same data as column-major. (The solver object itself is not kept:
/// Eigen's solvers are not copyable, and this struct should be.)
struct ImplicitEulerWorkspace {
  SpringBlockPattern pattern;                  ///< sparsity of A, rebuilt when the springs change
  std::vector<Eigen::Matrix3d> spring_blocks;  ///< #S  -(h df/dv + h^2 df/dx) per spring (kg)
  Eigen::Matrix3Xd spring_products;            ///< 3 x #S  K_s (v_i - v_j), K_s = df_i/dx_i (N/s)
  Eigen::VectorXd diagonal;                    ///< #P mass term m_i (1 + h c) (kg)
  Eigen::SparseMatrix<double, Eigen::RowMajor> system_matrix;  ///< 3#P x 3#P  A (kg)
  Eigen::VectorXd rhs;                                         ///< 3#P  b (kg m/s)
  Eigen::VectorXd velocity_change;     ///< 3#P  Delta v (m/s); the warm start of the next solve
  std::uint64_t warm_start_model = 0;  ///< SpringModel::identity velocity_change was solved for
  int cg_iterations = 0;               ///< conjugate gradient iterations of the last solve
};

}  // namespace tissu
