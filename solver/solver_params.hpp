#pragma once
/// \file
/// Parameters of a time step: the integrator, the time step and the environment's forces.

#include <Eigen/Core>
#include <vector>

#include "solver/collision/obstacle.hpp"
#include "solver/collision/self_collision.hpp"

namespace tissu {

enum class Integrator {
  symplectic_euler,     ///< v += h a(x, v); x += h v (semi-implicit Euler)
  position_verlet,      ///< Stormer-Verlet in leapfrog form, second order (course, Algorithm 2)
  implicit_euler,       ///< one linearised backward-Euler step (Baraff & Witkin 1998)
  projective_dynamics,  ///< backward Euler by local/global iterations (Liu et al. 2013; course,
                        ///< Algorithms 1-3); options in ProjectiveDynamicsOptions
  newton,               ///< backward Euler minimised to a tolerance by Newton's method, linear
                        ///< solves by PD-preconditioned CG; options in NewtonOptions
  quasi_newton,         ///< backward Euler minimised to a tolerance by L-BFGS, the PD matrix as
                        ///< initial Hessian (Liu et al. 2017); options in QuasiNewtonOptions
};

/// Wind blowing on the cloth faces; gusts modulate the mean velocity.
struct Wind {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< mean wind velocity (m/s)
  double gust_amplitude =
      0.0;  ///< relative gust strength a: w(t) = velocity (1 + a g(t)), |g| <= 1
  double gust_frequency = 0.0;    ///< main gust frequency f (Hz)
  double air_density = 1.2;       ///< rho_air (kg/m^3)
  double drag_coefficient = 1.0;  ///< C_d of a flat plate facing the flow, dimensionless
};

/// Forces that come from outside the cloth.
struct Environment {
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};  ///< g (m/s^2)
  double air_damping = 0.0;                  ///< mass-proportional drag c: f_i = -c m_i v_i (1/s)
  Wind wind;
};

/// Linear solve of the implicit integrator.
struct ImplicitOptions {
  /// relative residual |b - A dv| / |b| at which the conjugate gradient stops, dimensionless, > 0;
  /// 1e-5: tighter only costs time on the curtain (docs/benchmarks.md, solver defaults).
  double cg_tolerance = 1e-5;
  int cg_max_iterations = 1000;  ///< a step whose solve has not converged by then is NotConverged
};

/// How the global step of Projective Dynamics solves (M/h^2 + L) p = M/h^2 y + J d.
enum class PdGlobalSolver {
  direct,                ///< sparse LDL^T (Eigen SimplicialLDLT, METIS nested dissection),
                         ///< factorised once per model and h, solved on two threads
  jacobi,                ///< Jacobi sweeps, all particles from the previous iterate (parallel)
  chebyshev,             ///< Jacobi with Chebyshev semi-iterative acceleration (Wang 2015)
  gauss_seidel,          ///< sequential Gauss-Seidel in particle order (course's global step)
  colored_gauss_seidel,  ///< Gauss-Seidel colour by colour, each colour in parallel
                         ///< (Fratarcangeli et al. 2016; the course's red-black ordering)
  block_gauss_seidel,    ///< sequential Gauss-Seidel inside blocks of consecutive particles,
                         ///< blocks coloured so that those of one colour run in parallel
};

/// Iterations of the Projective Dynamics integrator (course, Algorithm 1).
struct ProjectiveDynamicsOptions {
  PdGlobalSolver global_solver = PdGlobalSolver::direct;  ///< solver of the global step
  /// local/global iterations per time step (numNonLinearIterations of Algorithm 1); with a
  /// tolerance, the maximum number. Liu et al. 2013 use 10.
  int iterations = 10;
  /// sweeps of the iterative global solvers per local step (numLinearIterations of Algorithm 1);
  /// ignored by the direct solver, which solves exactly.
  int linear_iterations = 1;
  /// stop early once max_i |p_i^k - p_i^(k-1)| <= tolerance * max_i |p_i^k - x_i| (change of the
  /// iterate relative to the step's displacement), dimensionless; 0 runs exactly `iterations`.
  /// A step that has not met a positive tolerance after `iterations` returns not_converged.
  double tolerance = 0.0;
  /// Iterative global solvers: after the iterations, a step whose estimated error exceeds this is
  /// not_converged, whatever `tolerance` says. The estimate is how far one exact solve of the last
  /// global step would still move the iterate, max_i |p*_i - p_i|, relative to how far the cloth's
  /// own forces move it in the step, max_i |p_i - y_i| from the inertial prediction y (or 1 % of
  /// h^2 max_i |f_ext,i| / m_i for a cloth falling unstretched): the fraction of the forces'
  /// effect the sweeps left out. Costs one factorisation of the global matrix per model and h, and
  /// one solve per step. The direct solver's global steps are exact: not checked. Dimensionless,
  /// >= 0; 0 turns it off. 0.02: an error of e in the forces' effect changes a spring-mass period
  /// by about e / 2 (Chebyshev at rho 0.95 on one spring leaves 0.0375, a 1.9 % longer period);
  /// the stiff sheet frozen by one-sweep solvers at h = 1/30 s scores 0.054 to 0.061 in every
  /// step; sheets the sweeps solve to within a millimetre of the direct solver stay below 0.02 in
  /// 97 % of their steps or more (docs/benchmarks.md, "Unconverged steps").
  double max_estimated_error = 0.02;
  /// Chebyshev: estimate rho of the spectral radius of the (relaxed) Jacobi iteration, in [0, 1),
  /// dimensionless; 0 = Gershgorin's bound max_i sum_j s_ij / (m_i/h^2 + sum_j s_ij), relaxed as
  /// 1 - gamma (1 - bound): an upper bound, too large inside PD for stiff cloth. 0.95 keeps a
  /// margin below the rho at which PD diverges (docs/benchmarks.md, solver defaults).
  double chebyshev_spectral_radius = 0.95;
  /// Chebyshev: under-relaxation gamma of each Jacobi sweep, p = gamma p_jacobi + (1 - gamma) p,
  /// in (0, 1]; damps the highest-frequency modes that Jacobi alone flips (Wang 2015 under-relaxes
  /// Jacobi the same way).
  double chebyshev_relaxation = 0.9;
  /// Chebyshev: sweeps of plain (relaxed) Jacobi before the acceleration starts (Wang 2015's S),
  /// counted over the whole time step; values below 1 act as 1 (the first sweep is plain Jacobi).
  int chebyshev_delay = 0;
};

/// Minimisation of backward Euler's incremental potential by the quasi-Newton integrator.
/// L-BFGS's initial inverse Hessian H_0^-1: the PD matrix M/h^2 + L (Liu, Bouaziz & Kavan 2017),
/// solved exactly or approximately.
enum class QuasiNewtonInitialHessian {
  pd_matrix,     ///< its sparse Cholesky factor: an exact solve, whose cost grows with the factor's
                 ///< fill (17 to 19 times from 81 x 81 to 256 x 256 particles)
  pd_multigrid,  ///< the default: one smoothed-aggregation V-cycle (pd_multigrid.hpp), near-linear
                 ///< cost, no factorisation after a remesh; an approximate inverse, with which the
                 ///< correction test of `tolerance` alone stops steps early (the stiff sheet at
                 ///< 1e-2 hung 0.77 m above the converged motion): keep gradient_reduction
                 ///< (docs/benchmarks.md)
};

struct QuasiNewtonOptions {
  /// the step stops once its last quasi-Newton correction is at most tolerance times the step's
  /// displacement (as NewtonOptions::tolerance), in (0, 1], dimensionless. On stiff cloth this
  /// bounds the last correction, not the error: L-BFGS crawls along the cloth's soft modes, and at
  /// 1e-2 the stiff hanging sheet's motion is 7 to 15 cm (mean) off the converged one, at 1e-3
  /// within 1 cm, 4 to 5 times slower (docs/benchmarks.md, "Converged steps at frame rate")
  double tolerance = 1e-2;
  int max_iterations = 200;  ///< a step that has not met the tolerance by then is not_converged
  int history = 5;           ///< L-BFGS pairs kept, >= 0 (Liu et al. 2017 keep 5; 0: PD-like)
  QuasiNewtonInitialHessian initial_hessian = QuasiNewtonInitialHessian::pd_multigrid;
  /// in [0, 1]: when > 0, a step also stops only once its gradient's norm is at most this
  /// fraction of the step's first, or of the tolerance's share of the forces the step balances
  /// (tolerance F, F = step_force_scale()) when that is larger, so that a cloth starting the step
  /// in balance is not held to reduce round-off; 0: the correction test alone. The correction test
  /// alone stops L-BFGS early on the soft modes, the more so with the V-cycle: at 0.1 the stiff
  /// sheet's motion is 5 to 6 % from the converged one with either initial Hessian (11.6 % and 51 %
  /// without), and the iterations per step no longer grow with the sheet (docs/benchmarks.md)
  double gradient_reduction = 0.1;
  /// a step that reaches max_iterations is finished by Newton's method from L-BFGS's last iterate
  /// (params.newton's options, with this tolerance and the multigrid preconditioner); false: it
  /// ends there, not converged
  bool newton_fallback = true;
};

/// Preconditioner of the conjugate gradient inside each Newton iteration.
enum class NewtonPreconditioner {
  multigrid,  ///< one V-cycle of aggregation multigrid on the Hessian itself (linear cost)
  pd_matrix,  ///< a solve with the prefactorised PD matrix M/h^2 + L (isotropic: blind to how
              ///< much softer a taut cloth is across its springs than along them)
};

/// Minimisation of backward Euler's incremental potential by the Newton integrator.
struct NewtonOptions {
  /// the step stops once its last Newton correction max_i |dx_i| is at most tolerance times the
  /// step's displacement max_i |x_i - x_n,i| (the measure of ProjectiveDynamicsOptions::
  /// tolerance), in (0, 1], dimensionless. 1e-2: the stiff sheet and the curtain at h = 1/30 s
  /// hang and fold as at 1e-3 (docs/benchmarks.md, "Converged steps at frame rate")
  double tolerance = 1e-2;
  int max_iterations = 20;      ///< a step that has not met the tolerance by then is not_converged
  int cg_max_iterations = 200;  ///< conjugate gradient iterations per Newton iteration, at most
  /// the step also has to bring its gradient's norm down to this fraction of its first (as
  /// QuasiNewtonOptions::gradient_reduction), in [0, 1]; 0: the correction test alone. A small
  /// correction is not a small gradient where the Hessian is locally much stiffer than the step:
  /// a particle starting to slide under friction in the step (its stiffness 2F/e at rest) creeps
  /// by a fraction of e, and the correction test alone held it fast
  double gradient_reduction = 0.1;
  /// multigrid: 1.8 to 2.9 times faster than pd_matrix on the stiff hanging sheet from 41 x 41 to
  /// 256 x 256 particles, as close to the converged motion (docs/benchmarks.md, "Newton
  /// preconditioned by multigrid")
  NewtonPreconditioner preconditioner = NewtonPreconditioner::multigrid;
};

struct SolverParams {
  Integrator integrator = Integrator::implicit_euler;
  double time_step = 1e-3;  ///< h (s), one step; a frame is several steps
  Environment environment;
  ImplicitOptions implicit;
  ProjectiveDynamicsOptions pd;
  NewtonOptions newton;
  QuasiNewtonOptions quasi_newton;
  std::vector<Obstacle> obstacles;  ///< kept out of after every step, whatever the integrator
  /// beta (dimensionless, >= 0): Newton and quasi-Newton also hold the obstacles inside the step,
  /// by a penalty of stiffness beta m / h^2 per particle (contact_planes.hpp; a particle resting
  /// on a floor sinks g h^2 / beta into its thickness during the step, and is projected out after
  /// it); 0: obstacles act only after the step, as for the other integrators
  double obstacle_penalty = 0.0;
  /// with obstacle_penalty: Coulomb friction inside the step too, its normal force lagged from the
  /// last step, or estimated at the step's start where there is none, as after a remesh
  /// (lag_contact_friction(); Li et al. 2020), so that friction cannot hold a particle its
  /// springs pull harder than mu times its normal force (after the step alone, on velocity, it
  /// holds stretched springs of a stiff cloth lying on a floor: the drape's corners rested 28 %
  /// stretched, 2 % with it); 0.9 to 1.15 times the time of the garment and drape demos
  /// (docs/benchmarks.md, "twenty-second session"). false: friction after the step only
  bool friction_in_step = true;
  SelfCollisionOptions self_collision;  ///< the cloth against itself, after every step
  /// the largest relative stretch of a structural spring (dimensionless, e.g. 0.1 for 10 %),
  /// imposed after every step, after the contacts (strain_limit.hpp); 0: none
  double strain_limit = 0.0;
};

}  // namespace tissu
