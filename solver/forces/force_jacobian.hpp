#pragma once
/// \file
/// Sparse Jacobians of the total force (accumulate_forces.hpp) with respect to positions and
/// velocities, as used by implicit integrators.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "solver/forces/spring_block_matrix.hpp"
#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

struct ForceJacobianOptions {
  /// Use spring_force_jacobian_clamped() (negative semidefinite, what an implicit solver needs)
  /// instead of the exact spring_force_jacobian(); they differ only for compressed springs.
  bool clamp_compressed_springs = false;
};

/// Scratch buffers of the Jacobian assembly, kept by the caller; meaningless between calls.
struct ForceJacobianWorkspace {
  SpringBlockPattern pattern;                  ///< sparsity, rebuilt only when the springs change
  std::vector<Eigen::Matrix3d> spring_blocks;  ///< #S per-spring 3x3 blocks (N/m or N s/m)
  Eigen::VectorXd diagonal;                    ///< #P per-particle diagonal term (N s/m)
  Eigen::VectorXd spring_stretch;              ///< #S |d| - l0 (m), with couplings only
  Eigen::VectorXd coupling_tension;            ///< #S tension the couplings add (N)
};

/// Position Jacobian df/dx (3#P x 3#P, N/m, symmetric) at positions x (3#P, m): per spring the
/// blocks of spring_force_jacobian() (Baraff & Witkin 1998; Choi & Ko 2002),
/// df_i/dxi = df_j/dxj = K, df_i/dxj = df_j/dxi = -K, plus the couplings' terms
/// (spring_coupling.hpp), clamped like the springs'. Left out, as in Baraff & Witkin 1998: the
/// position dependence of the viscous spring force (not symmetric; zero at rest) and the
/// aerodynamic force, which integrators treat explicitly. Gravity and air damping do not depend
/// on x. Deterministic for any number of OpenMP threads.
void force_position_jacobian(const SpringModel& model, const Eigen::VectorXd& x,
                             const ForceJacobianOptions& options, ForceJacobianWorkspace& workspace,
                             Eigen::SparseMatrix<double>& dfdx);

/// Velocity Jacobian df/dv (3#P x 3#P, N s/m, symmetric negative semidefinite) at positions x
/// (3#P, m): per spring the blocks of spring_damping_force_jacobian(), D = -nu u u^T, plus the
/// air damping -c m_i I on the diagonal. Exact for the forces of accumulate_forces() except the
/// aerodynamic force, treated explicitly. Deterministic for any number of OpenMP threads.
void force_velocity_jacobian(const SpringModel& model, const Environment& environment,
                             const Eigen::VectorXd& x, ForceJacobianWorkspace& workspace,
                             Eigen::SparseMatrix<double>& dfdv);

}  // namespace tissu
