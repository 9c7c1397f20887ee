// Particles against obstacles: resting, sliding with Coulomb friction, not tunnelling.

#include "solver/collision/obstacle_contacts.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr double g = 9.81;  // m/s^2

SolverParams params_with(Integrator integrator, const Obstacle& obstacle) {
  SolverParams params;
  params.integrator = integrator;
  params.time_step = 1e-3;
  params.environment.gravity = {0.0, 0.0, -g};
  params.obstacles = {obstacle};
  return params;
}

class EveryIntegrator : public ::testing::TestWithParam<Integrator> {};

TEST_P(EveryIntegrator, AParticleRestingOnAFloorStaysOnItFor10000Steps) {
  Obstacle floor;
  floor.thickness_m = 0.004;
  State state;
  const SpringModel model = test::lone_particle({0.1, 0.2, 0.05}, Eigen::Vector3d::Zero(), state);
  const SolverParams params = params_with(GetParam(), floor);
  StepWorkspace workspace;
  for (int n = 0; n < 10000; ++n) {
    ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
    ASSERT_GE(state.x.z(), floor.thickness_m * (1.0 - 1e-12)) << "step " << n;
  }
  EXPECT_NEAR(state.x.z(), floor.thickness_m, 1e-9);
  EXPECT_NEAR(state.v.norm(), 0.0, 1e-9);
  EXPECT_EQ(workspace.obstacle_contacts, 1);
}

TEST_P(EveryIntegrator, AParticleDroppedOnASphereEndsOutsideIt) {
  Obstacle ball;
  ball.shape = ObstacleShape::sphere;
  ball.radius_m = 0.3;
  ball.static_friction = ball.kinetic_friction = 0.3;
  State state;
  const SpringModel model = test::lone_particle({0.05, 0.0, 1.0}, Eigen::Vector3d::Zero(), state);
  const SolverParams params = params_with(GetParam(), ball);
  StepWorkspace workspace;
  for (int n = 0; n < 3000; ++n) {
    ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
    ASSERT_GE(state.x.head<3>().norm(), ball.radius_m + ball.thickness_m - 1e-9) << "step " << n;
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, EveryIntegrator,
                         ::testing::Values(Integrator::symplectic_euler,
                                           Integrator::position_verlet, Integrator::implicit_euler,
                                           Integrator::projective_dynamics),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(ObstacleFriction, StaticFrictionHoldsAParticleOnASlope) {
  // tan 20 deg = 0.36 < mu_s = 0.5: it never starts sliding
  const Obstacle plane = test::slope(20.0 * M_PI / 180.0, 0.5, 0.4);
  State state;
  const Eigen::Vector3d start = plane.thickness_m * plane.normal;
  const SpringModel model = test::lone_particle(start, Eigen::Vector3d::Zero(), state);
  const SolverParams params = params_with(Integrator::symplectic_euler, plane);
  for (int n = 0; n < 2000; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  EXPECT_LT((state.x - start).norm(), 1e-12);
  EXPECT_LT(state.v.norm(), 1e-12);
}

TEST(ObstacleFriction, KineticFrictionSlowsASlidingParticleAsCoulombSays) {
  // down a 30-degree slope with mu_k = 0.3: a = g (sin 30 - 0.3 cos 30) = 2.36 m/s^2 along it
  const double angle_rad = 30.0 * M_PI / 180.0;
  const Obstacle plane = test::slope(angle_rad, 0.3, 0.3);
  const Eigen::Vector3d down_slope(0.0, -std::cos(angle_rad), -std::sin(angle_rad));
  State state;
  const Eigen::Vector3d start = plane.thickness_m * plane.normal;
  const SpringModel model = test::lone_particle(start, Eigen::Vector3d::Zero(), state);
  const SolverParams params = params_with(Integrator::symplectic_euler, plane);
  const double duration_s = 1.0;
  for (int n = 0; n < 1000; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  const double a = g * (std::sin(angle_rad) - 0.3 * std::cos(angle_rad));
  EXPECT_NEAR(state.v.dot(down_slope), a * duration_s, 0.02 * a * duration_s);
  EXPECT_NEAR((state.x - start).dot(down_slope), 0.5 * a * duration_s * duration_s,
              0.02 * 0.5 * a * duration_s * duration_s);
  EXPECT_NEAR((state.x - start).dot(plane.normal), 0.0, 1e-12);  // on the slope throughout

  // a particle thrown up-flat on a level floor stops after v^2 / (2 mu_k g)
  const Obstacle floor = test::slope(0.0, 0.3, 0.3);
  const Eigen::Vector3d on_floor_start = floor.thickness_m * floor.normal;  // touching, not in it
  const SpringModel thrown =
      test::lone_particle(on_floor_start, Eigen::Vector3d(2.0, 0.0, 0.0), state);
  const SolverParams on_floor = params_with(Integrator::symplectic_euler, floor);
  for (int n = 0; n < 2000; ++n) ASSERT_EQ(step(thrown, on_floor, state), StepStatus::ok);
  const double stopping_m = 2.0 * 2.0 / (2.0 * 0.3 * g);
  EXPECT_NEAR(state.x.x() - on_floor_start.x(), stopping_m, 0.02 * stopping_m);
  EXPECT_EQ(state.v.x(), 0.0);
}

TEST(ObstacleContacts, AFastParticleDoesNotTunnelThroughAThinWall) {
  // a 2 mm wall, and a particle covering 5 cm per step towards it: from x = -0.02 m to 0.03 m
  // in one step, clear of the wall at both ends
  Obstacle wall;
  wall.shape = ObstacleShape::box;
  wall.half_extents_m = {0.001, 1.0, 1.0};
  wall.thickness_m = 0.002;
  State state;
  const SpringModel model =
      test::lone_particle({-0.52, 0.0, 0.0}, Eigen::Vector3d(50.0, 0.0, 0.0), state);
  SolverParams params = params_with(Integrator::symplectic_euler, wall);
  params.environment.gravity.setZero();
  for (int n = 0; n < 40; ++n) {
    ASSERT_EQ(step(model, params, state), StepStatus::ok);
    ASSERT_LE(state.x.x(), -0.003 + 1e-12) << "step " << n;
  }
  EXPECT_NEAR(state.x.x(), -0.003, 1e-12);  // stopped against it
}

TEST(ObstacleContacts, AFastThinWallSweepsAStillParticleAhead) {
  // a 2 cm wall moving at 30 m/s, 0.3 m per step: it jumps clear over the particle in one step,
  // but the particle's path relative to it crosses it, so it is met on the wall's front and
  // pushed ahead at the wall's speed
  constexpr double speed_m_per_s = 30.0;
  Obstacle wall;
  wall.shape = ObstacleShape::box;
  wall.position = {-0.5, 0.0, 0.0};
  wall.half_extents_m = {0.01, 1.0, 1.0};
  wall.motion.drift_m_per_s = {speed_m_per_s, 0.0, 0.0};
  State state;
  const SpringModel model = test::lone_particle({0.0, 0.0, 0.0}, Eigen::Vector3d::Zero(), state);
  SolverParams params = params_with(Integrator::symplectic_euler, wall);
  params.time_step = 0.01;
  params.environment.gravity.setZero();
  for (int n = 1; n <= 10; ++n) {
    ASSERT_EQ(step(model, params, state), StepStatus::ok);
    const double front_m = -0.5 + 0.01 + speed_m_per_s * n * params.time_step;
    if (front_m + wall.thickness_m > 0.0) {
      ASSERT_NEAR(state.x.x(), front_m + wall.thickness_m, 1e-9) << "step " << n;
      ASSERT_NEAR(state.v.x(), speed_m_per_s, 1e-9) << "step " << n;
    } else {
      ASSERT_EQ(state.x.x(), 0.0) << "step " << n;
    }
  }
}

TEST(ObstacleContacts, AFastClothDoesNotTunnelThroughAThinPlate) {
  // a 0.33 m sheet falling at 20 m/s (6.7 cm per step) onto a 2 mm plate wider than it
  State state;
  const SpringModel sheet = test::grid_model(12, 12, 0.03, 1e-4, 200.0, 0.01, state);
  for (int p = 0; p < sheet.particle_count(); ++p) {
    state.x[3 * p + 2] = 0.1;
    state.v[3 * p + 2] = -20.0;
  }
  Obstacle plate;
  plate.shape = ObstacleShape::box;
  plate.position = {0.15, 0.15, 0.0};
  plate.half_extents_m = {1.0, 1.0, 0.001};
  SolverParams params = params_with(Integrator::implicit_euler, plate);
  params.time_step = 1.0 / 300.0;
  for (int n = 0; n < 30; ++n) {
    ASSERT_EQ(step(sheet, params, state), StepStatus::ok);
    for (int p = 0; p < sheet.particle_count(); ++p) {
      ASSERT_GE(state.x[3 * p + 2], 0.001 + plate.thickness_m - 1e-9) << "step " << n;
    }
  }
}

TEST(ObstacleContacts, APathGrazingACurvedObstacleIsNotHeldBack) {
  // a leg of 6.5 cm radius; a particle 1 mm clear of its thickness flies along a chord of the
  // circle it is on, from -20 to +20 degrees: the chord dips into the thickness (to 1.7 mm from
  // the surface) but not into the leg, and it ends clear, where it is left. Held at its first
  // touch instead, a particle that a moving leg's surface carries was dragged along by the leg
  // while its springs stretched 27 times (skirt_walk.json, docs/benchmarks.md)
  Obstacle leg;
  leg.shape = ObstacleShape::capsule;
  leg.position = {0.0, 0.0, -1.0};
  leg.axis_end = {0.0, 0.0, 1.0};
  leg.radius_m = 0.065;
  const double radius_m = leg.radius_m + leg.thickness_m + 0.001;
  const double angle = 20.0 * M_PI / 180.0;
  const Eigen::Vector3d start(radius_m * std::cos(angle), -radius_m * std::sin(angle), 0.0);
  const Eigen::Vector3d end(start.x(), -start.y(), 0.0);
  SolverParams params = params_with(Integrator::symplectic_euler, leg);
  params.environment.gravity.setZero();
  params.time_step = 1.0 / 30.0;
  State state;
  const SpringModel model = test::lone_particle(start, (end - start) / params.time_step, state);
  ASSERT_EQ(step(model, params, state), StepStatus::ok);
  EXPECT_LT((state.x - end).norm(), 1e-12);

  // a chord from -40 to +40 degrees goes into the leg (to 5.4 cm from its axis): it is stopped
  // where it first touches the thickness, on its own side
  const double wide = 40.0 * M_PI / 180.0;
  const Eigen::Vector3d wide_start(radius_m * std::cos(wide), -radius_m * std::sin(wide), 0.0);
  const Eigen::Vector3d wide_end(wide_start.x(), -wide_start.y(), 0.0);
  State across;
  const SpringModel across_model =
      test::lone_particle(wide_start, (wide_end - wide_start) / params.time_step, across);
  ASSERT_EQ(step(across_model, params, across), StepStatus::ok);
  EXPECT_LT(across.x.y(), 0.0);  // before the chord's middle
  EXPECT_NEAR(Eigen::Vector2d(across.x.x(), across.x.y()).norm(), leg.radius_m + leg.thickness_m,
              1e-6);
}

TEST(ObstacleContacts, AParticleLeavingTheFloorIsLetGo) {
  // it starts exactly at the thickness, where a contact leaves it, and jumps up and sideways
  Obstacle floor;
  State state;
  const SpringModel model =
      test::lone_particle({0.0, 0.0, floor.thickness_m}, Eigen::Vector3d(1.0, 0.0, 2.0), state);
  SolverParams params = params_with(Integrator::implicit_euler, floor);
  for (int n = 0; n < 10; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  EXPECT_NEAR(state.x.x(), 0.01, 1e-12);
  EXPECT_GT(state.x.z(), floor.thickness_m + 0.015);
}

TEST(ObstacleContacts, AMovingObstacleCarriesTheParticleAndPinsStay) {
  // a floor rising at 1 m/s lifts a particle resting on it; a pinned particle is not touched
  Obstacle lift;
  lift.motion.drift_m_per_s = {0.0, 0.0, 1.0};
  State state;
  SpringModel model =
      test::lone_particle({0.0, 0.0, lift.thickness_m}, Eigen::Vector3d::Zero(), state);
  const SolverParams params = params_with(Integrator::implicit_euler, lift);
  for (int n = 0; n < 500; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  EXPECT_NEAR(state.x.z(), 0.5 + lift.thickness_m, 1e-9);
  EXPECT_NEAR(state.v.z(), 1.0, 1e-9);

  model.pinned[0] = 1;
  finalize_model(model);
  state.x = Eigen::Vector3d(0.0, 0.0, -1.0);
  state.v.setZero();
  for (int n = 0; n < 10; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  EXPECT_EQ(state.x.z(), -1.0);
}

/// A 2 m x 2 m turntable whose top is at z = 0, turning about z at `omega` rad/s for 10 s.
Obstacle turntable(double omega_rad_per_s, double friction) {
  Obstacle plate;
  plate.shape = ObstacleShape::box;
  plate.position = {0.0, 0.0, -0.05};
  plate.half_extents_m = {1.0, 1.0, 0.05};
  plate.static_friction = plate.kinetic_friction = friction;
  plate.motion.pivot_m = Eigen::Vector3d::Zero();
  plate.motion.keys = {{0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                       {10.0, Eigen::Vector3d::Zero(), {0.0, 0.0, 10.0 * omega_rad_per_s}}};
  return plate;
}

TEST(ObstacleContacts, ARotatingPlateCarriesAParticleByFriction) {
  // half a turn per second, 0.5 m out: 1.57 m/s, and omega^2 r = 4.9 m/s^2 of centripetal
  // acceleration, which friction (mu g = 9.8 m/s^2) can give
  constexpr double omega = M_PI, radius_m = 0.5;
  const Obstacle plate = turntable(omega, 1.0);
  State state;
  SpringModel model =
      test::lone_particle({radius_m, 0.0, plate.thickness_m}, Eigen::Vector3d::Zero(), state);
  const SolverParams params = params_with(Integrator::implicit_euler, plate);
  for (int n = 0; n < 1000; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  const double angle_at_1s = std::atan2(state.x.y(), state.x.x());
  for (int n = 0; n < 500; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  const double angle_at_1_5s = std::atan2(state.x.y(), state.x.x());  // a quarter turn later

  // it caught up with the plate (in mu g / (omega r) ~ 0.16 s) and turns with it
  EXPECT_NEAR(std::remainder(angle_at_1_5s - angle_at_1s, 2 * M_PI), omega * 0.5, 0.02);
  EXPECT_NEAR(std::hypot(state.x.x(), state.x.y()), radius_m, 0.01);
  EXPECT_NEAR(state.v.norm(), omega * radius_m, 0.03);
  EXPECT_NEAR(state.x.z(), plate.thickness_m, 1e-6);

  // without friction the plate turns under it and it stays where it was
  const Obstacle slippery = turntable(omega, 0.0);
  model =
      test::lone_particle({radius_m, 0.0, slippery.thickness_m}, Eigen::Vector3d::Zero(), state);
  const SolverParams slippery_params = params_with(Integrator::implicit_euler, slippery);
  for (int n = 0; n < 1000; ++n) ASSERT_EQ(step(model, slippery_params, state), StepStatus::ok);
  EXPECT_NEAR(state.x.x(), radius_m, 1e-9);
  EXPECT_NEAR(state.x.y(), 0.0, 1e-9);
}

}  // namespace
}  // namespace tissu
