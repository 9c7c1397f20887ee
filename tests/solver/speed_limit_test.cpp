// The speed limit that tells a blow-up from motion: what it adds up, that legitimate motion stays
// under it, and that an explicit step too large for its spring crosses it at once.

#include "solver/speed_limit.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr double mass_kg = 0.5;
constexpr double stiffness_n_per_m = 200.0;
constexpr double stretch_m = 0.1;

// one mass on one spring (rest length 1 m) whose other end is pinned, stretched by `stretch_m`
SpringModel stretched_spring(State& state) {
  return test::spring_mass(mass_kg, stiffness_n_per_m, 1.0, stretch_m, state);
}

double fastest_free_speed(const SpringModel& model, const State& state) {
  double fastest = 0.0;
  for (int p = 0; p < model.particle_count(); ++p) {
    if (model.inverse_mass[p] != 0.0) fastest = std::max(fastest, state.v.segment<3>(3 * p).norm());
  }
  return fastest;
}

TEST(SpeedLimit, AddsGravityOverTheElapsedTimeObstaclesWindAndTheStartingStretch) {
  State state;
  const SpringModel model = stretched_spring(state);
  state.time = 2.0;
  state.v[0] = 0.3;  // a pinned end moving as a handle
  SolverParams params;
  params.environment.gravity = {0.0, 0.0, -9.81};
  params.environment.wind.velocity = {0.0, 2.0, 0.0};
  params.environment.wind.gust_amplitude = 0.5;
  Obstacle ball;
  ball.shape = ObstacleShape::sphere;
  ball.motion.keys = {{0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                      {1.0, {0.0, 0.0, -0.5}, Eigen::Vector3d::Zero()},
                      {3.0, {0.0, 0.0, -0.6}, Eigen::Vector3d::Zero()}};
  ball.motion.drift_m_per_s = {0.1, 0.0, 0.0};
  params.obstacles = {ball};

  const SpeedLimit limit = speed_limit_at_start(model, params, state);
  EXPECT_DOUBLE_EQ(limit.start_time_s, 2.0);
  EXPECT_DOUBLE_EQ(limit.initial_speed_m_per_s, 0.3);
  EXPECT_DOUBLE_EQ(limit.obstacle_speed_m_per_s, 0.1 + 0.5);  // drift + fastest segment
  EXPECT_DOUBLE_EQ(limit.wind_speed_m_per_s, 3.0);
  EXPECT_DOUBLE_EQ(limit.gravity_m_per_s2, 9.81);
  // the stretched spring's energy all in the free mass: amplitude x omega
  const double release = stretch_m * std::sqrt(stiffness_n_per_m / mass_kg);
  EXPECT_NEAR(limit.release_speed_m_per_s, release, 1e-12);
  const double sum = 0.3 + release + 0.6 + 3.0 + 9.81 * 0.5;
  EXPECT_NEAR(speed_limit_m_per_s(limit, 2.5), limit.margin * sum, 1e-9);
}

TEST(SpeedLimit, ATearWidensItByTheRecoilOfTheStretchItReleases) {
  State state;
  const SpringModel model = stretched_spring(state);
  state.x[3] = 1.0;  // at rest length: nothing to release at the start
  SolverParams params;
  params.environment.gravity.setZero();
  SpeedLimit limit = speed_limit_at_start(model, params, state);
  EXPECT_DOUBLE_EQ(limit.release_speed_m_per_s, 0.0);
  state.x[3] = 1.0 + 2.0 * stretch_m;  // pulled, then torn or cut
  widen_for_release(limit, model, state);
  const double release = 2.0 * stretch_m * std::sqrt(stiffness_n_per_m / mass_kg);
  EXPECT_NEAR(limit.release_speed_m_per_s, release, 1e-12);
  state.x[3] = 1.0;  // a later tear with less stretch keeps the larger recoil
  widen_for_release(limit, model, state);
  EXPECT_NEAR(speed_limit_m_per_s(limit, 0.0), limit.margin * release, 1e-9);
}

TEST(SpeedLimit, AReleasedSpringAndAFallingParticleStayUnderIt) {
  for (const Integrator integrator :
       {Integrator::symplectic_euler, Integrator::position_verlet, Integrator::implicit_euler}) {
    State state;
    const SpringModel model = stretched_spring(state);
    SolverParams params;
    params.integrator = integrator;
    params.time_step = 1e-3;
    params.environment.gravity.setZero();
    const SpeedLimit limit = speed_limit_at_start(model, params, state);
    double worst = 0.0;  // largest speed / limit
    for (int n = 0; n < 2000; ++n) {
      step(model, params, state);
      ASSERT_FALSE(find_overspeed(limit, model, state)) << to_string(integrator) << " step " << n;
      worst = std::max(worst,
                       fastest_free_speed(model, state) / speed_limit_m_per_s(limit, state.time));
    }
    // the oscillator's top speed is exactly the spring's release speed: 1 / margin of the limit
    EXPECT_LT(worst, 1.01 / limit.margin) << to_string(integrator);
    EXPECT_GT(worst, 0.9 / limit.margin) << to_string(integrator);
  }
  State state;
  const SpringModel model =
      test::lone_particle(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), state);
  SolverParams params;
  params.integrator = Integrator::symplectic_euler;
  params.time_step = 1e-2;
  const SpeedLimit limit = speed_limit_at_start(model, params, state);
  for (int n = 0; n < 300; ++n) {
    step(model, params, state);
    ASSERT_FALSE(find_overspeed(limit, model, state)) << "falling, step " << n;
  }
}

TEST(SpeedLimit, AnExplicitStepTooLargeForItsSpringCrossesItWithinTwoSteps) {
  State state;
  const SpringModel model = stretched_spring(state);
  SolverParams params;
  params.integrator = Integrator::symplectic_euler;
  params.time_step = 0.5;  // h omega = 10: each step multiplies the motion by about 100
  params.environment.gravity.setZero();
  const SpeedLimit limit = speed_limit_at_start(model, params, state);
  int first_over = -1;
  for (int n = 1; n <= 10 && first_over < 0; ++n) {
    ASSERT_NE(step(model, params, state), StepStatus::non_finite);
    if (const auto over = find_overspeed(limit, model, state)) {
      first_over = n;
      EXPECT_EQ(over->particle, 1);
      EXPECT_GT(over->speed_m_per_s, over->limit_m_per_s);
    }
  }
  EXPECT_GE(first_over, 1);
  EXPECT_LE(first_over, 2);
}

TEST(SpeedLimit, PinnedParticlesAreNotChecked) {
  State state;
  const SpringModel model = stretched_spring(state);
  SolverParams params;
  const SpeedLimit limit = speed_limit_at_start(model, params, state);
  state.v[0] = 1e6;  // the pinned end, as prescribed
  EXPECT_FALSE(find_overspeed(limit, model, state));
  state.v[3] = 1e6;  // the free end
  const auto over = find_overspeed(limit, model, state);
  ASSERT_TRUE(over);
  EXPECT_EQ(over->particle, 1);
  EXPECT_DOUBLE_EQ(over->speed_m_per_s, 1e6);
}

}  // namespace
}  // namespace tissu
