#pragma once
/// \file
/// Iterative solvers of Projective Dynamics' global step (see pd_system.hpp):
///   a_i p_i - sum_j s_ij p_j = c_i for every free particle i, pinned p_j held fixed.
/// Positions p and right-hand side c are 3#P vectors, xyz interleaved; the three coordinates
/// share the matrix and are updated together.

#include <Eigen/Core>

#include "solver/pd/pd_system.hpp"
#include "solver/solver_params.hpp"

namespace tissu {

/// Buffers and memory of the iterative solvers, kept between sweeps (and across the local steps
/// of a time step, for Chebyshev). Sized on first use.
struct PdIterativeState {
  Eigen::VectorXd next;      ///< 3#P the iterate being computed (m)
  Eigen::VectorXd previous;  ///< 3#P Chebyshev's q^(k-1) (m)
  double omega = 1.0;        ///< Chebyshev's last weight omega_k
  int sweeps = 0;            ///< sweeps since reset_pd_iterative_state()
};

/// Starts a new sequence of sweeps from the iterate p (3#P): q^(-1) = q^0 = p, k = 0.
void reset_pd_iterative_state(const Eigen::VectorXd& p, PdIterativeState& state);

/// One Jacobi sweep with relaxation gamma in (0, 1]:
///   p_i <- gamma (c_i + sum_j s_ij p_j) / a_i + (1 - gamma) p_i, all i from the previous iterate.
/// Course, "Méthode Jacobi"; the course's global step with every p_j from iteration k. Parallel,
/// identical for any thread count.
void pd_jacobi_sweep(const PdSystem& system, const Eigen::VectorXd& c, double relaxation,
                     Eigen::VectorXd& p, PdIterativeState& state);

/// One Chebyshev semi-iterative sweep on top of relaxed Jacobi (Wang 2015, "A Chebyshev
/// semi-iterative approach for accelerating projective and position-based dynamics", eq. 12):
///   q^(k+1) = omega_(k+1) (gamma (q_jacobi - q^k) + q^k - q^(k-1)) + q^(k-1),
///   omega = 1 for k < S, 2 / (2 - rho^2) for k = S, 4 / (4 - rho^2 omega_k) after, S >= 1,
/// rho the spectral radius estimate of the relaxed Jacobi matrix. Parallel, thread-count
/// independent.
void pd_chebyshev_sweep(const PdSystem& system, const Eigen::VectorXd& c, double relaxation,
                        double spectral_radius, int delay, Eigen::VectorXd& p,
                        PdIterativeState& state);

/// One Gauss-Seidel sweep in ascending particle order, in place (the course's global step:
/// p_i^(k+1) = (m_i/h^2 y_i + sum_(j<i) s_ij (p_j^(k+1) + d_ij) + sum_(j>i) s_ij (p_j^k + d_ij))
/// / (m_i/h^2 + sum s_ij)). Sequential.
void pd_gauss_seidel_sweep(const PdSystem& system, const Eigen::VectorXd& c, Eigen::VectorXd& p);

/// One Gauss-Seidel sweep colour by colour (system.coloring), each colour's particles in
/// parallel: no two of them share a spring, so they read only other colours' values and the
/// result is the same for any thread count (course, Algorithm 1 with red-black sets generalised
/// to a graph colouring; Fratarcangeli et al. 2016, "Vivace").
void pd_colored_gauss_seidel_sweep(const PdSystem& system, const Eigen::VectorXd& c,
                                   Eigen::VectorXd& p);

/// One block Gauss-Seidel sweep: sequential Gauss-Seidel in ascending order inside each block of
/// consecutive free particles (system.block_offsets), block colour by block colour, the blocks of
/// one colour in parallel. They share no spring, so the result is the same for any thread count.
/// Each block streams its own rows and positions once, as sequential Gauss-Seidel does, where
/// the particle-coloured sweep reads all positions once per colour. (A block-level multicolour
/// ordering, as in parallel SOR; the blocks' coloring stands in for the course's red-black sets.)
void pd_block_gauss_seidel_sweep(const PdSystem& system, const Eigen::VectorXd& c,
                                 Eigen::VectorXd& p);

/// Chebyshev's rho from the options: options.chebyshev_spectral_radius if positive, otherwise
/// 1 - gamma (1 - system.jacobi_radius_bound) (Gershgorin's bound, relaxed).
double pd_chebyshev_spectral_radius(const PdSystem& system,
                                    const ProjectiveDynamicsOptions& options);

/// `sweeps` sweeps of options.global_solver (which must not be direct) on p.
void pd_iterative_solve(const PdSystem& system, const ProjectiveDynamicsOptions& options,
                        const Eigen::VectorXd& c, int sweeps, Eigen::VectorXd& p,
                        PdIterativeState& state);

}  // namespace tissu
