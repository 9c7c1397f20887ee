#include "solver/step.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

const Integrator all_integrators[] = {Integrator::symplectic_euler, Integrator::position_verlet,
                                      Integrator::implicit_euler,   Integrator::projective_dynamics,
                                      Integrator::newton,           Integrator::quasi_newton};

// a 12 x 10 sheet, 0.55 m x 0.45 m in the z = 0 plane, held by two corners (particles 0 and 11)
SpringModel sheet(State& state) {
  SpringModel model = test::grid_model(12, 10, 0.05, 0.002, 200.0, 0.01, state);
  model.pinned[0] = 1;
  model.pinned[11] = 1;
  finalize_model(model);
  return model;
}

SolverParams windy_params(Integrator integrator) {
  SolverParams params;
  params.integrator = integrator;
  params.time_step = 5e-4;
  params.environment.air_damping = 0.1;
  params.environment.wind.velocity = Eigen::Vector3d(0.0, 0.0, 3.0);
  params.environment.wind.gust_amplitude = 0.4;
  params.environment.wind.gust_frequency = 1.5;
  return params;
}

TEST(Step, PinnedParticlesStayFixed) {
  for (const Integrator integrator : all_integrators) {
    State state;
    const SpringModel model = sheet(state);
    const State initial = state;
    const SolverParams params = windy_params(integrator);
    StepWorkspace workspace;
    for (int n = 0; n < 400; ++n) {
      ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok)
          << "integrator " << static_cast<int>(integrator) << ", step " << n;
    }
    for (const int pinned : {0, 11}) {
      EXPECT_EQ(Eigen::Vector3d(state.x.segment<3>(3 * pinned)),
                Eigen::Vector3d(initial.x.segment<3>(3 * pinned)));
      EXPECT_TRUE(state.v.segment<3>(3 * pinned).isZero());
    }
    // the free particles did fall
    EXPECT_LT(state.x[3 * 115 + 2], initial.x[3 * 115 + 2] - 0.01);
  }
}

TEST(Step, PinnedParticlesKeepTheirPrescribedVelocity) {
  for (const Integrator integrator : all_integrators) {
    State state;
    const SpringModel model = sheet(state);
    const Eigen::Vector3d drive(0.2, 0.0, 0.1);
    state.v.segment<3>(0) = drive;
    const Eigen::Vector3d start = state.x.segment<3>(0);
    const SolverParams params = windy_params(integrator);
    StepWorkspace workspace;
    const int steps = 100;
    for (int n = 0; n < steps; ++n)
      ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
    EXPECT_EQ(Eigen::Vector3d(state.v.segment<3>(0)), drive);
    const Eigen::Vector3d moved = state.x.segment<3>(0) - start;
    EXPECT_LT((moved - steps * params.time_step * drive).norm(), 1e-12);
  }
}

TEST(Step, NonFiniteInputGivesNonFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Integrator integrator : all_integrators) {
    State state;
    const SpringModel model = sheet(state);
    const SolverParams params = windy_params(integrator);
    State with_nan = state;
    with_nan.x[3 * 40 + 1] = nan;
    EXPECT_EQ(step(model, params, with_nan), StepStatus::non_finite);
    State with_inf = state;
    with_inf.v[3 * 7] = inf;
    EXPECT_EQ(step(model, params, with_inf), StepStatus::non_finite);
  }
}

TEST(Step, ExplodingExplicitStepIsReportedNotSilent) {
  // symplectic Euler far beyond its stability limit h < 2 sqrt(m / k)
  State state;
  SpringModel model = test::grid_model(6, 6, 0.05, 1e-4, 1e5, 0.0, state);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Eigen::Index i = 0; i < state.x.size(); ++i) state.x[i] += 0.005 * unit(rng);
  SolverParams params;
  params.integrator = Integrator::symplectic_euler;
  params.time_step = 1e-2;
  StepWorkspace workspace;
  StepStatus status = StepStatus::ok;
  for (int n = 0; n < 2000 && status == StepStatus::ok; ++n) {
    status = step(model, params, state, workspace);
  }
  EXPECT_EQ(status, StepStatus::non_finite);
}

TEST(Step, ImplicitEulerIsStableAtLargeTimeSteps) {
  State state;
  const SpringModel model = sheet(state);
  SolverParams params = windy_params(Integrator::implicit_euler);
  params.time_step = 1.0 / 60.0;  // symplectic Euler needs h < 2 sqrt(m/k) = 6 ms here
  StepWorkspace workspace;
  for (int n = 0; n < 300; ++n) ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
  // the sheet hangs: nothing went further than its size below the pins
  EXPECT_GT(state.x.reshaped(3, model.particle_count()).row(2).minCoeff(), -1.0);
}

TEST(Step, ImplicitEulerReportsNotConverged) {
  State state;
  const SpringModel model = sheet(state);
  SolverParams params = windy_params(Integrator::implicit_euler);
  params.time_step = 1.0 / 60.0;
  params.implicit.cg_max_iterations = 1;
  params.implicit.cg_tolerance = 1e-12;
  step(model, params, state);
  EXPECT_EQ(step(model, params, state), StepStatus::not_converged);
}

TEST(Step, AdvancesTime) {
  State state;
  const SpringModel model = sheet(state);
  const SolverParams params = windy_params(Integrator::position_verlet);
  StepWorkspace workspace;
  for (int n = 0; n < 10; ++n) step(model, params, state, workspace);
  EXPECT_NEAR(state.time, 10 * params.time_step, 1e-15);
}

TEST(Step, RejectsAStateOfTheWrongSize) {
  State state;
  const SpringModel model = sheet(state);
  state.v.resize(6);
  EXPECT_THROW(step(model, windy_params(Integrator::implicit_euler), state), std::invalid_argument);
}

TEST(Step, BitwiseIdenticalForOneAndTwoThreads) {
  for (const Integrator integrator : all_integrators) {
    State initial;
    SpringModel model = test::grid_model(20, 20, 0.025, 0.001, 300.0, 0.01, initial);
    model.pinned[0] = 1;
    model.pinned[19] = 1;
    finalize_model(model);
    const SolverParams params = windy_params(integrator);
    const auto results = test::step_with_one_and_two_threads(model, params, initial, 30);
    EXPECT_TRUE((results[0].x.array() == results[1].x.array()).all());
    EXPECT_TRUE((results[0].v.array() == results[1].v.array()).all());
    EXPECT_NE(results[0].x, initial.x);
  }
}

TEST(Step, StatusNames) {
  EXPECT_STREQ(to_string(StepStatus::ok), "ok");
  EXPECT_STREQ(to_string(StepStatus::non_finite), "non_finite");
  EXPECT_STREQ(to_string(StepStatus::not_converged), "not_converged");
}

}  // namespace
}  // namespace tissu
