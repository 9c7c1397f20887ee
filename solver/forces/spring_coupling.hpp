#pragma once
/// \file
/// Couplings between the stretches of two springs (SpringModel::couplings): energy
///   W_c = Gamma_c dl_a dl_b,   dl_s = |x_i - x_j| - l0_s for spring s = (i, j),
/// the angular terms of Delingette 2008's triangular springs, linearised
/// (topology/membrane_stiffness.hpp). Their gradient lies along the two springs:
///   f_i = -Gamma_c dl_b u_a on spring a's first end (and the opposite on its second end),
/// an extra tension Gamma_c dl_b in spring a, and likewise in b. Their force Jacobian is
///   df/dx = -Gamma_c (g_a g_b^T + g_b g_a^T) - Gamma_c dl_b H_a - Gamma_c dl_a H_b,
/// g_s = (u_s on i, -u_s on j) the gradient of dl_s and H_s its Hessian, (I - u u^T)/|d| in
/// Laplacian blocks: the last two terms are the geometric stiffness of the extra tensions, which
/// fit the per-spring blocks; the first one joins the ends of two springs.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solver/forces/spring_block_matrix.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Stretch dl_s of every spring (#S, m) and the tension its couplings add to it,
/// T_a = sum over couplings c of a of Gamma_c dl_b (#S, N). Gathered per spring in coupling
/// order: deterministic for any number of threads.
void spring_coupling_tensions(const SpringModel& model, const Eigen::VectorXd& x,
                              Eigen::VectorXd& stretch_m, Eigen::VectorXd& tension_n);

/// sum over couplings of Gamma_c dl_a dl_b (J).
double spring_coupling_energy(const SpringModel& model, const Eigen::VectorXd& x);

/// The geometric-stiffness block of an extra tension T (N) in spring (xi, xj):
/// -(T / |d|) (I - u u^T), the df_i/dxi block (N/m); with clamp, T < 0 counts as 0, which keeps
/// the Jacobian negative semidefinite (as spring_force_jacobian_clamped does).
Eigen::Matrix3d coupling_tension_jacobian(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj,
                                          double tension_n, bool clamp);

/// Adds, for each spring a, the couplings' cross term of (df/dx) v that lands on a's ends:
/// -sum over couplings c of a of Gamma_c u_a (u_b . (v_k - v_l)), b = (k, l), to
/// products.col(a) (3 x #S, N/s), which the caller gathers with +1 on a's first end and -1 on
/// its second. Deterministic.
void add_coupling_velocity_products(const SpringModel& model, const Eigen::VectorXd& x,
                                    const Eigen::VectorXd& v, Eigen::Matrix3Xd& products);

/// Adds scale x the cross blocks -Gamma_c (g_a g_b^T + g_b g_a^T) of df/dx to `matrix`, assembled
/// on `pattern` by assemble_spring_block_matrix(). Every pair of particles of two coupled springs
/// must be joined by a spring (finalize_model checks it). With filter_pinned, rows and columns of
/// particles with inverse_mass 0 are left as they are. Rows are filled in parallel, each in
/// coupling order: deterministic.
template <int StorageOrder>
void add_coupling_jacobian_blocks(const SpringModel& model, const SpringBlockPattern& pattern,
                                  const Eigen::VectorXd& x, double scale, bool filter_pinned,
                                  Eigen::SparseMatrix<double, StorageOrder>& matrix);

}  // namespace tissu
