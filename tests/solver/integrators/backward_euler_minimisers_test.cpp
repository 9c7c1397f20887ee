// Newton and quasi-Newton on backward Euler's incremental potential: the exact step, the damped
// backward-Euler equation, their tolerance, pins, thread counts and recompiled models; and the
// convergence check of Projective Dynamics' weak global solvers.

#include <gtest/gtest.h>

#include <cmath>

#include "solver/forces/accumulate_forces.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/step.hpp"
#include "tests/solver/backward_euler_reference.hpp"
#include "tests/solver/test_models.hpp"
#include "tests/test_thread_count.hpp"

namespace tissu {
namespace {

// the integrators that minimise the step's potential, and quasi-Newton's two initial Hessians
struct Minimiser {
  Integrator integrator;
  QuasiNewtonInitialHessian initial_hessian;
  const char* name;
};
const Minimiser minimisers[] = {
    {Integrator::newton, QuasiNewtonInitialHessian::pd_matrix, "newton"},
    {Integrator::quasi_newton, QuasiNewtonInitialHessian::pd_matrix, "quasi_newton"},
    {Integrator::quasi_newton, QuasiNewtonInitialHessian::pd_multigrid,
     "quasi_newton/pd_multigrid"},
};

SolverParams minimiser(const Minimiser& method, double h, double tolerance) {
  SolverParams params;
  params.integrator = method.integrator;
  params.quasi_newton.initial_hessian = method.initial_hessian;
  params.time_step = h;
  params.environment.wind.air_density = 0.0;
  params.newton.tolerance = params.quasi_newton.tolerance = tolerance;
  params.newton.max_iterations = params.quasi_newton.max_iterations = 1000;
  return params;
}

TEST(BackwardEulerMinimisers, ReachTheExactBackwardEulerStep) {
  // without damping the minimiser of the incremental potential is the backward-Euler step, which
  // a dense Newton solve of M (x1 - x0 - h v0) / h^2 = f(x1) + M g gives to round-off
  for (const Minimiser& method : minimisers) {
    for (const double h : {1e-3, 1.0 / 60.0}) {
      State state;
      const SpringModel model = test::perturbed_sheet(state, 0.0, 7);
      const SolverParams params = minimiser(method, h, 1e-12);
      const Eigen::VectorXd reference =
          test::backward_euler_positions(model, state, h, params.environment.gravity);
      const double displacement = (reference - state.x).lpNorm<Eigen::Infinity>();
      State stepped = state;
      ASSERT_EQ(step(model, params, stepped), StepStatus::ok) << method.name << " h " << h;
      EXPECT_LT((stepped.x - reference).lpNorm<Eigen::Infinity>(), 1e-9 * displacement)
          << method.name << " h " << h;
      EXPECT_LT((stepped.v - (reference - state.x) / h).lpNorm<Eigen::Infinity>(),
                1e-9 * displacement / h);
    }
  }
}

TEST(BackwardEulerMinimisers, SolveTheDampedBackwardEulerEquation) {
  // with spring and air damping, the converged step satisfies, at every free particle,
  //   m (v1 - v0) / h = m g + f_springs(x1) - c m v1 - sum nu ((v1_i - v1_j) . u0) u0,
  // u0 the spring's direction at the start of the step; checked here term by term, independently
  // of the potential's code, to 1e-8 of the weight
  for (const Minimiser& method : minimisers) {
    State state;
    const SpringModel model = test::perturbed_sheet(state, 0.3, 5);
    SolverParams params = minimiser(method, 1.0 / 30.0, 1e-12);
    params.environment.air_damping = 0.4;
    const double c = params.environment.air_damping;
    const double h = params.time_step;
    State stepped = state;
    ASSERT_EQ(step(model, params, stepped), StepStatus::ok) << method.name;
    Eigen::VectorXd imbalance = Eigen::VectorXd::Zero(state.x.size());
    for (int p = 0; p < model.particle_count(); ++p) {
      imbalance.segment<3>(3 * p) =
          model.mass[p] * ((stepped.v - state.v).segment<3>(3 * p) / h -
                           params.environment.gravity + c * stepped.v.segment<3>(3 * p));
    }
    for (int s = 0; s < model.spring_count(); ++s) {
      const int i = model.springs(s, 0), j = model.springs(s, 1);
      const Eigen::Vector3d u0 =
          (state.x.segment<3>(3 * i) - state.x.segment<3>(3 * j)).normalized();
      const Eigen::Vector3d f =
          spring_force(stepped.x.segment<3>(3 * i), stepped.x.segment<3>(3 * j), model.stiffness[s],
                       model.rest_length[s]) -
          model.damping[s] * u0.dot(stepped.v.segment<3>(3 * i) - stepped.v.segment<3>(3 * j)) * u0;
      imbalance.segment<3>(3 * i) -= f;
      imbalance.segment<3>(3 * j) += f;
    }
    double weight_n = 0.0;
    for (int p = 0; p < model.particle_count(); ++p) {
      if (model.pinned[p]) {
        imbalance.segment<3>(3 * p).setZero();
      } else {
        weight_n = std::max(weight_n, model.mass[p] * params.environment.gravity.norm());
      }
    }
    EXPECT_LT(imbalance.lpNorm<Eigen::Infinity>(), 1e-8 * weight_n) << method.name;
  }
}

TEST(BackwardEulerMinimisers, SolveTheBackwardEulerEquationWithCouplings) {
  // Delingette's couplings (spring_coupling.hpp), which Projective Dynamics cannot take: the
  // converged step satisfies m (v1 - v0) / h = f(x1) + m g with f the springs' and couplings'
  // forces of accumulate_forces(), to 1e-8 of the weight
  for (const Minimiser& method : minimisers) {
    State state;
    SpringModel model = test::perturbed_sheet(state, 0.0, 11);
    test::couple_triangle_edges(model, 4);
    model.coupling_stiffness *= 0.2;  // within +-60 N/m of the springs' 100: a convex energy
    finalize_model(model);
    const SolverParams params = minimiser(method, 1.0 / 60.0, 1e-12);
    const double h = params.time_step;
    State stepped = state;
    ASSERT_EQ(step(model, params, stepped), StepStatus::ok) << method.name;
    ForceWorkspace forces;
    Eigen::VectorXd force;
    accumulate_forces(model, params.environment, 0.0, stepped.x,
                      Eigen::VectorXd::Zero(stepped.v.size()), forces, force);
    double largest_n = 0.0;
    for (int p = 0; p < model.particle_count(); ++p) {
      if (model.pinned[p]) continue;
      const Eigen::Vector3d imbalance =
          model.mass[p] * (stepped.v - state.v).segment<3>(3 * p) / h - force.segment<3>(3 * p);
      largest_n = std::max(largest_n, imbalance.norm());
    }
    EXPECT_LT(largest_n, 1e-8 * model.mass[6] * params.environment.gravity.norm()) << method.name;
  }
}

TEST(BackwardEulerMinimisers, StopAtTheirToleranceAndSaySoWhenTheyCannot) {
  // the stiff sheet at h = 1/30 s: the default tolerance is met; one iteration is not enough
  for (const Minimiser& method : minimisers) {
    State initial;
    const SpringModel model = test::stiff_sheet(21, initial);
    SolverParams params = minimiser(method, 1.0 / 30.0, 1e-2);
    params.newton.max_iterations = params.quasi_newton.max_iterations = 200;
    State state = initial;
    StepWorkspace workspace;
    for (int frame = 0; frame < 10; ++frame) {
      ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok)
          << method.name << " frame " << frame;
    }
    const double ratio = method.integrator == Integrator::newton
                             ? workspace.newton.correction_ratio
                             : workspace.quasi_newton.correction_ratio;
    EXPECT_LE(ratio, 1e-2);
    params.newton.max_iterations = params.quasi_newton.max_iterations = 1;
    params.newton.tolerance = params.quasi_newton.tolerance = 1e-9;
    EXPECT_EQ(step(model, params, state, workspace), StepStatus::not_converged) << method.name;
    EXPECT_TRUE(state.x.allFinite());
  }
}

TEST(QuasiNewtonStop, AGradientReductionHoldsEachStepUntilItsGradientFalls) {
  // the stiff sheet with the V-cycle as initial Hessian: the correction test alone lets some step
  // end with more than a tenth of its first gradient; with gradient_reduction 0.1 none does
  State initial;
  const SpringModel model = test::stiff_sheet(21, initial);
  double largest_ratio[2] = {0.0, 0.0};
  int iterations[2] = {0, 0};
  for (int reduced = 0; reduced < 2; ++reduced) {
    SolverParams params = minimiser(minimisers[2], 1.0 / 30.0, 1e-2);
    params.quasi_newton.max_iterations = 200;
    params.quasi_newton.gradient_reduction = reduced ? 0.1 : 0.0;
    State state = initial;
    StepWorkspace workspace;
    for (int frame = 0; frame < 20; ++frame) {
      ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok) << frame;
      largest_ratio[reduced] =
          std::max(largest_ratio[reduced], workspace.quasi_newton.gradient_ratio);
      iterations[reduced] += workspace.quasi_newton.iterations;
    }
  }
  EXPECT_GT(largest_ratio[0], 0.1);
  EXPECT_LE(largest_ratio[1], 0.1);
  EXPECT_GT(iterations[1], iterations[0]);
}

TEST(QuasiNewtonStop, AGradientReductionAsksNoMoreThanTheToleranceOfAClothAtRest) {
  // the stiff sheet hanging at rest: its first gradient is what is left of the settling steps,
  // far below the tolerance's share of its weight, and the reduction is measured from that share,
  // which the first iterate meets (from the first gradient itself: 130 to 150 iterations)
  State state;
  const SpringModel model = test::stiff_sheet(11, state);
  state.x += 1e-3 * test::random_free_vector(model, 5);  // off the flat sheet's saddle
  // Newton steps of h = 1 s from rest, each from the last at rest: the sheet settles
  const SolverParams settle = minimiser(minimisers[0], 1.0, 1e-10);
  StepWorkspace settle_workspace;
  for (int n = 0; n < 3; ++n) {
    ASSERT_EQ(step(model, settle, state, settle_workspace), StepStatus::ok) << n;
    state.v.setZero();
  }
  for (const int method : {1, 2}) {
    SolverParams params = minimiser(minimisers[method], 1.0 / 30.0, 1e-2);
    params.quasi_newton.max_iterations = 200;
    params.quasi_newton.gradient_reduction = 0.1;
    State stepped = state;
    StepWorkspace workspace;
    EXPECT_EQ(step(model, params, stepped, workspace), StepStatus::ok) << minimisers[method].name;
    EXPECT_LE(workspace.quasi_newton.iterations, 3) << minimisers[method].name;
    EXPECT_LT((stepped.x - state.x).lpNorm<Eigen::Infinity>(), 1e-6) << minimisers[method].name;
  }
}

TEST(QuasiNewtonFallback, NewtonFinishesAStepLbfgsCannotAndReachesItsMinimiser) {
  // the stiff sheet's first step at a tolerance two L-BFGS iterations cannot meet: Newton's
  // iterations from L-BFGS's last iterate converge it, to the step Newton alone takes
  State initial;
  const SpringModel model = test::stiff_sheet(21, initial);
  State reference = initial;
  ASSERT_EQ(step(model, minimiser(minimisers[0], 1.0 / 30.0, 1e-10), reference), StepStatus::ok);
  const double displacement = (reference.x - initial.x).lpNorm<Eigen::Infinity>();
  for (const int method : {1, 2}) {
    SolverParams params = minimiser(minimisers[method], 1.0 / 30.0, 1e-6);
    params.quasi_newton.max_iterations = 2;
    params.newton.max_iterations = 50;
    State state = initial;
    StepWorkspace workspace;
    EXPECT_EQ(step(model, params, state, workspace), StepStatus::ok) << minimisers[method].name;
    EXPECT_EQ(workspace.quasi_newton.iterations, 2) << minimisers[method].name;
    EXPECT_GT(workspace.quasi_newton.newton_iterations, 0) << minimisers[method].name;
    EXPECT_EQ(last_step_iterations(params, workspace), 2 + workspace.newton.iterations);
    EXPECT_LT((state.x - reference.x).lpNorm<Eigen::Infinity>(), 1e-4 * displacement)
        << minimisers[method].name;

    params.quasi_newton.newton_fallback = false;
    State without = initial;
    EXPECT_EQ(step(model, params, without, workspace), StepStatus::not_converged)
        << minimisers[method].name;
    EXPECT_EQ(workspace.quasi_newton.newton_iterations, 0) << minimisers[method].name;
  }
}

TEST(BackwardEulerMinimisers, PinnedParticlesFollowTheirVelocityAndTheSheetFalls) {
  for (const Minimiser& method : minimisers) {
    State state;
    SpringModel model = test::perturbed_sheet(state, 0.1, 3);
    const State initial = state;
    state.v.segment<3>(0) = Eigen::Vector3d(0.0, 0.0, 0.5);  // a pinned corner moving up
    const SolverParams params = minimiser(method, 1.0 / 60.0, 1e-3);
    StepWorkspace workspace;
    for (int n = 0; n < 60; ++n) ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
    EXPECT_NEAR(state.x[2], initial.x[2] + 0.5 * 60 / 60.0, 1e-12);
    EXPECT_EQ(Eigen::Vector3d(state.x.segment<3>(15)), Eigen::Vector3d(initial.x.segment<3>(15)));
    EXPECT_LT(state.x[3 * 33 + 2], initial.x[3 * 33 + 2] - 0.05) << method.name;
  }
}

TEST(BackwardEulerMinimisers, IdenticalForOneAndTwoThreads) {
  for (const Minimiser& method : minimisers) {
    State initial;
    SpringModel model = test::grid_model(20, 20, 0.025, 0.001, 300.0, 0.05, initial);
    model.pinned[0] = 1;
    model.pinned[19] = 1;
    finalize_model(model);
    SolverParams params = minimiser(method, 1.0 / 30.0, 1e-3);
    params.environment.wind.air_density = 1.2;
    params.environment.wind.velocity = Eigen::Vector3d(0.0, 0.0, 3.0);
    const auto results = test::step_with_one_and_two_threads(model, params, initial, 10);
    EXPECT_TRUE((results[0].x.array() == results[1].x.array()).all()) << method.name;
    EXPECT_TRUE((results[0].v.array() == results[1].v.array()).all()) << method.name;
    EXPECT_NE(results[0].x, initial.x);
  }
}

TEST(BackwardEulerMinimisers, AReusedWorkspaceFollowsARecompiledModel) {
  // the preconditioner, its factorisation and the Hessian's pattern are keyed on the model's
  // identity: stepping another model (here: one more pin, other stiffnesses) with the same
  // workspace gives the fresh workspace's bits
  for (const Minimiser& method : minimisers) {
    State state;
    SpringModel model = test::perturbed_sheet(state, 0.1, 9);
    const SolverParams params = minimiser(method, 1.0 / 60.0, 1e-4);
    StepWorkspace reused;
    State first = state;
    ASSERT_EQ(step(model, params, first, reused), StepStatus::ok);
    model.pinned[30] = 1;
    model.stiffness *= 2.0;
    finalize_model(model);
    State again = state, fresh = state;
    StepWorkspace new_workspace;
    ASSERT_EQ(step(model, params, again, reused), StepStatus::ok);
    ASSERT_EQ(step(model, params, fresh, new_workspace), StepStatus::ok);
    EXPECT_TRUE((again.x.array() == fresh.x.array()).all()) << method.name;
    EXPECT_TRUE((again.v.array() == fresh.v.array()).all()) << method.name;
  }
}

TEST(ProjectiveDynamicsCheck, AWeakGlobalSolverOnStiffClothIsReportedNotConverged) {
  // the course's coloured Gauss-Seidel, one sweep per local step, on the stiff sheet at
  // h = 1/30 s barely moves it (docs/benchmarks.md): its steps must say so; the direct solver's
  // steps, with the same 10 iterations, pass the same check
  State initial;
  const SpringModel model = test::stiff_sheet(31, initial);
  for (const PdGlobalSolver solver :
       {PdGlobalSolver::colored_gauss_seidel, PdGlobalSolver::direct}) {
    SolverParams params;
    params.integrator = Integrator::projective_dynamics;
    params.time_step = 1.0 / 30.0;
    params.pd.global_solver = solver;
    State state = initial;
    StepWorkspace workspace;
    int unconverged = 0;
    for (int frame = 0; frame < 30; ++frame) {
      unconverged += step(model, params, state, workspace) == StepStatus::not_converged;
    }
    if (solver == PdGlobalSolver::direct) {
      EXPECT_EQ(unconverged, 0);
    } else {
      EXPECT_GE(unconverged, 15) << "estimated error of the last step "
                                 << workspace.pd.estimated_error;
    }
    params.pd.max_estimated_error = 0.0;  // the check off: every step ok
    EXPECT_EQ(step(model, params, state, workspace), StepStatus::ok);
  }
}

// lowest height (m) of a sheet after `steps` steps of PD with `solver` and `linear_iterations`,
// and how many of those steps said not_converged
struct SheetRun {
  double lowest_z_m = 0.0;
  int unconverged = 0;
};

SheetRun soft_windy_sheet(PdGlobalSolver solver, int linear_iterations, int steps) {
  // 6 x 6 particles 0.2 m apart, 10 g each, 100 N/m, in wind, two corners pinned, h = 1/60 s
  State state;
  SpringModel model = test::grid_model(6, 6, 0.2, 0.01, 100.0, 0.05, state);
  model.pinned[30] = model.pinned[35] = 1;
  finalize_model(model);
  SolverParams params;
  params.integrator = Integrator::projective_dynamics;
  params.time_step = 1.0 / 60.0;
  params.environment.wind.velocity = {1.0, 0.0, 1.0};
  params.pd.global_solver = solver;
  params.pd.linear_iterations = linear_iterations;
  StepWorkspace workspace;
  SheetRun run;
  for (int n = 0; n < steps; ++n) {
    run.unconverged += step(model, params, state, workspace) == StepStatus::not_converged;
  }
  run.lowest_z_m = state.x.reshaped(3, state.x.size() / 3).row(2).minCoeff();
  return run;
}

TEST(ProjectiveDynamicsCheck, ASoftSheetTheSweepsLeaveBehindIsFlaggedAndOneTheySolveIsNot) {
  // measured against the step's displacement, one Jacobi sweep per local step passed on this
  // sheet while it hung 6 cm above the direct solver's: against what the forces do in the step,
  // it fails, and 16 sweeps, within a millimetre of the direct solver, pass
  const int steps = 200;
  const double direct_z = soft_windy_sheet(PdGlobalSolver::direct, 1, steps).lowest_z_m;
  const SheetRun one_sweep = soft_windy_sheet(PdGlobalSolver::jacobi, 1, steps);
  EXPECT_GT(std::abs(one_sweep.lowest_z_m - direct_z), 0.02);
  EXPECT_GE(one_sweep.unconverged, steps * 9 / 10);
  const SheetRun sixteen_sweeps = soft_windy_sheet(PdGlobalSolver::jacobi, 16, steps);
  EXPECT_LT(std::abs(sixteen_sweeps.lowest_z_m - direct_z), 1e-3);
  EXPECT_EQ(sixteen_sweeps.unconverged, 0);
}

}  // namespace
}  // namespace tissu
