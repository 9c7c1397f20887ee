#pragma once
/// \file
/// Backward Euler's incremental potential for the springs, the function that every implicit
/// integrator minimises (Martin et al. 2011, "Example-based elastic materials"; Liu et al. 2013,
/// eq. 7; Gast et al. 2015, "Optimization integrator for large time steps"):
///   E(x) = sum over free i of [ m_i/(2h^2) |x_i - y_i|^2 + c m_i/(2h) |x_i - x_n,i|^2 ]
///        + sum over springs s of [ k_s/2 (|d_s| - l_s)^2 + nu_s/(2h) ((d_s - d_n,s) . u_n,s)^2 ]
///        + sum over couplings c of Gamma_c dl_a dl_b
///        + sum over contact planes of k/2 max(0, (p - x_i) . n)^2                         (J),
/// with y = x_n + h v_n + h^2 f_ext / m (gravity and wind at the start of the step), d_s =
/// x_i - x_j, u_n,s the spring's direction at the start of the step. Its minimiser is the backward
/// Euler step x_{n+1}, v_{n+1} = (x_{n+1} - x_n)/h: grad E = 0 is
///   m (v_{n+1} - v_n)/h = f_ext + f_springs(x_{n+1}) - c m v_{n+1} + f_viscous(v_{n+1}),
/// where the viscous spring force -nu ((v_i - v_j) . u) u is taken along the start direction u_n
/// (Rayleigh damping with the direction lagged by one step, which makes its potential quadratic).
/// Pinned particles are fixed at x_n + h v_n and have no terms of their own.

#include <Eigen/Core>
#include <algorithm>

#include "solver/collision/contact_planes.hpp"
#include "solver/forces/symmetric_block_matrix.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// What one step's potential is built from; the vectors are the caller's (not copied).
struct StepPotential {
  double time_step_s = 0.0;                   ///< h (s)
  const Eigen::VectorXd* start_x = nullptr;   ///< 3#P x_n (m)
  const Eigen::VectorXd* inertial = nullptr;  ///< 3#P y (m)
  double air_damping = 0.0;                   ///< c (1/s), taken implicitly
  /// obstacle contacts held inside the step (their penalties are added to E), or none
  const std::vector<ContactPlane>* contacts = nullptr;
};

/// Per-spring scratch of evaluate_step_potential(); meaningless between calls.
struct StepPotentialWorkspace {
  Eigen::Matrix3Xd spring_forces;       ///< 3 x #S force of each spring on its first end (N)
  Eigen::Matrix3Xd start_directions;    ///< 3 x #S u_n, filled by prepare_step_potential()
  Eigen::VectorXd start_projections_m;  ///< #S d_n . u_n (m), filled by prepare_step_potential()
  Eigen::VectorXd spring_stretch;       ///< #S |d| - l (m), with couplings only
  Eigen::VectorXd coupling_tension;     ///< #S tension the couplings add (N)
  bool viscous = false;  ///< some spring has damping, so the viscous terms are evaluated
};

/// Fills what the potential keeps for the whole step: the start directions u_n and projections
/// d_n . u_n, and whether any spring is viscous.
void prepare_step_potential(const SpringModel& model, const StepPotential& potential,
                            StepPotentialWorkspace& workspace);

/// Each spring's force on its first end (N) into workspace.spring_forces at x, elastic plus
/// viscous along the start direction; returns the sum of their energies (J), added in fixed chunks
/// (parallel_sum.hpp). Springs in parallel, in loops the compiler
/// vectorises: AVX2 where the processor has it (`kernel`, as the block products choose), else
/// SSE2. The two round differently, so a run's bits depend on the processor, never on the number
/// of threads. With AVX2 the potential took 1.2 to 1.75 times less than with the scalar loop
/// before it, at 81^2 to 256^2 particles (docs/benchmarks.md, "2026-12-07").
double evaluate_spring_terms(const SpringModel& model, double time_step_s, const Eigen::VectorXd& x,
                             StepPotentialWorkspace& workspace,
                             BlockProductKernel kernel = block_product_kernel());

/// E(x) (J); with a gradient, also grad E (3#P, N), zero on pinned particles. Springs in parallel
/// into per-spring buffers, then gathered per particle in model.incidence order and summed in a
/// fixed order: the same bits for any number of OpenMP threads.
double evaluate_step_potential(const SpringModel& model, const StepPotential& potential,
                               const Eigen::VectorXd& x, StepPotentialWorkspace& workspace,
                               Eigen::VectorXd* gradient);

/// The step's first iterate x_0 = x_n + h v_n (also the pinned particles' final positions) and
/// the inertial target y = x_0 + h^2 f_ext / m (3#P each, m), from f_ext (3#P, N).
void predict_step(const SpringModel& model, double time_step_s, const State& state,
                  const Eigen::VectorXd& external_force, Eigen::VectorXd& first_iterate,
                  Eigen::VectorXd& inertial);

/// Backtracking line search on E from x along `direction` d (a descent direction, whose slope
/// grad E . d (J) the caller gives): tries alpha = 1, 1/2, 1/4, ... (at most 30 halvings) until
/// the sufficient decrease of Armijo, E(x + alpha d) <= E(x) + 1e-4 alpha grad E . d, holds, a
/// decrease within round-off of E (1e-13 |E|) counting as one (Hager & Zhang 2005's approximate
/// Wolfe test: near the minimum E's differences drown in its size). True with trial_x,
/// trial_gradient, trial_energy_j set.
bool backtracking_line_search(const SpringModel& model, const StepPotential& potential,
                              const Eigen::VectorXd& x, double slope_j, double energy_j,
                              const Eigen::VectorXd& direction, StepPotentialWorkspace& workspace,
                              Eigen::VectorXd& trial_x, Eigen::VectorXd& trial_gradient,
                              double& trial_energy_j);

/// max_i |dx_i| / max(max_i |x_i - x_n,i|, a max_i h^2 |f_ext,i| / m_i) over the free particles:
/// a correction dx (3#P, m) of the iterate x (3#P, m) relative to the step's displacement from
/// x_n (3#P, m), or to the fraction a (dimensionless) of what the external forces f_ext (3#P, N)
/// move a particle in one step when that is larger (so that a cloth at rest, which hardly moves,
/// is measured against its sag under gravity, not against zero). Dimensionless; the convergence
/// measure of Newton and quasi-Newton (a = 1) and of PD's check. Allocates nothing.
double relative_correction(const SpringModel& model, double time_step_s,
                           const Eigen::VectorXd& correction, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& start_x, const Eigen::VectorXd& external_force,
                           double external_fraction);

/// The force scale that the residual of a step is measured against (N): |F|_2 over the free
/// particles, F_i = m_i (y_i - x_n,i)/h^2 = m_i v_n,i/h + f_ext,i, the momentum and the external
/// forces the step has to balance (a cloth at rest: its weight).
double step_force_scale(const SpringModel& model, const StepPotential& potential);

/// The gradient norm a minimiser's gradient_reduction is a fraction of (N): the step's first
/// gradient, or the tolerance's share of the forces the step balances (step_force_scale()) when
/// that is larger, so that a cloth starting the step in balance is not held to reduce round-off.
inline double gradient_reduction_reference(double first_gradient_n, double tolerance,
                                           double force_scale_n) {
  return std::max(first_gradient_n, tolerance * force_scale_n);
}

/// The stop of Newton's and quasi-Newton's steps: the last correction at most `tolerance` times
/// the step's displacement (relative_correction()) and, with `gradient_reduction` > 0, the
/// gradient at most that fraction of gradient_reduction_reference() (`gradient_ratio`).
inline bool minimiser_converged(double correction_ratio, double tolerance, double gradient_ratio,
                                double gradient_reduction) {
  return correction_ratio <= tolerance &&
         (gradient_reduction == 0.0 || gradient_ratio <= gradient_reduction);
}

/// Relative residual |grad E(x)|_2 / F, dimensionless: the force still out of balance as a
/// fraction of the forces the step balances (F = step_force_scale()); when F is 0 (no motion, no
/// external force), relative to |grad E(x_0)|_2 at the first iterate instead; 0 for 0 / 0.
double relative_residual(double gradient_norm_n, double force_scale_n,
                         double first_gradient_norm_n);

}  // namespace tissu
