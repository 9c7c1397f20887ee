// Obstacle contacts inside the minimisers' step: which particles get a plane, the penalty's
// gradient, where it holds a particle, and the friction it gives at frame-rate steps.

#include "solver/collision/contact_planes.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr double g = 9.81;         // m/s^2
constexpr double h = 1.0 / 30.0;   // s: one step per frame
constexpr double penalty = 100.0;  // beta

SolverParams minimiser_params(Integrator integrator, const Obstacle& obstacle) {
  SolverParams params;
  params.integrator = integrator;
  params.time_step = h;
  params.environment.gravity = {0.0, 0.0, -g};
  params.obstacles = {obstacle};
  params.obstacle_penalty = penalty;
  return params;
}

// each coordinate of `gradient` (N) is the central difference of the planes' energy at x with
// step dx (m), within absolute + relative |difference|
void expect_central_differences(const std::vector<ContactPlane>& planes, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& gradient, double dx, double absolute,
                                double relative) {
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Eigen::VectorXd plus = x, minus = x;
    plus[i] += dx;
    minus[i] -= dx;
    const double slope = (add_contact_potential(planes, plus, nullptr) -
                          add_contact_potential(planes, minus, nullptr)) /
                         (2.0 * dx);
    EXPECT_NEAR(gradient[i], slope, absolute + relative * std::abs(slope)) << "coordinate " << i;
  }
}

TEST(ContactPlanes, OnlyFreeParticlesWithinReachOfAnObstacleGetAPlane) {
  // four particles above a floor of thickness 5 mm: touching, 8 mm up, 2 cm up but falling 2 cm
  // in the step, 2 cm up and still; the first pinned in a second model
  SpringModel model = test::free_particles(4);
  Eigen::VectorXd start(12), first(12);
  start << 0, 0, 0.005, 1, 0, 0.008, 2, 0, 0.02, 3, 0, 0.02;
  first = start;
  first[8] = 0.0;  // the third falls 2 cm
  Obstacle floor;
  floor.thickness_m = 0.005;
  std::vector<ContactPlane> planes;
  find_contact_planes(model, {floor}, penalty, h, h, start, first, planes);
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_EQ(planes[0].particle, 0);
  EXPECT_EQ(planes[1].particle, 1);
  EXPECT_EQ(planes[2].particle, 2);
  for (const ContactPlane& plane : planes) {
    EXPECT_NEAR(plane.point.z(), floor.thickness_m, 1e-15);
    EXPECT_EQ(plane.normal, Eigen::Vector3d::UnitZ());
    EXPECT_DOUBLE_EQ(plane.stiffness_n_per_m, penalty * 0.01 / (h * h));
  }
  find_contact_planes(model, {floor}, 0.0, h, h, start, first, planes);
  EXPECT_TRUE(planes.empty()) << "beta = 0 holds nothing inside the step";
  model.pinned[0] = 1;
  model.inverse_mass[0] = 0.0;
  find_contact_planes(model, {floor}, penalty, h, h, start, first, planes);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].particle, 1);
}

TEST(ContactPlanes, APlaneNeverPutsTheStepsStartDeeperThanTheThicknessBelowIt) {
  // On a ball of radius 0.5 m (thickness 5 mm) two particles start on its top. The first is
  // predicted 2 degrees further round: it is held by the tangent plane there, which its start is
  // a little below ((R + t)(1 - cos 2 deg) = 0.3 mm). The second, a torn lip flung round the ball,
  // is predicted 60 degrees round: the tangent plane there would put its start 25 cm deep and
  // throw it, and no plane holds its path round the ball: it gets none (the projection after the
  // step keeps it out).
  SpringModel model = test::free_particles(2);
  Obstacle ball;
  ball.shape = ObstacleShape::sphere;
  ball.radius_m = 0.5;
  ball.thickness_m = 0.005;
  const double r = ball.radius_m + ball.thickness_m;
  const auto round = [&](double degrees) {
    const double a = degrees * M_PI / 180.0;
    return Eigen::Vector3d(r * std::sin(a), 0.0, r * std::cos(a));
  };
  Eigen::VectorXd start(6), first(6);
  start << round(0.0), round(0.0);
  first << round(2.0), round(60.0);
  std::vector<ContactPlane> planes;
  find_contact_planes(model, {ball}, penalty, h, h, start, first, planes);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].particle, 0);
  EXPECT_LT((planes[0].normal - round(2.0) / r).norm(), 1e-12);
  EXPECT_NEAR(contact_depth_m(planes[0], round(0.0)), r * (1.0 - std::cos(2.0 * M_PI / 180.0)),
              1e-12);
}

TEST(ContactPlanes, APenaltysGradientIsItsEnergysDerivative) {
  std::vector<ContactPlane> planes(3);
  planes[0] = {0, 0, {0.0, 0.0, 0.01}, Eigen::Vector3d(0.0, 0.6, 0.8), 300.0};
  planes[1] = {1, 0, {1.0, 0.0, 0.0}, Eigen::Vector3d::UnitX(), 50.0};  // not reached
  planes[2] = {0, 1, {0.0, 0.0, 0.0}, Eigen::Vector3d::UnitZ(), 120.0};
  Eigen::VectorXd x(6);
  x << 0.002, -0.003, -0.004, 1.5, 0.0, 0.0;
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(6);
  const double energy_j = add_contact_potential(planes, x, &gradient);
  EXPECT_GT(energy_j, 0.0);
  EXPECT_EQ(gradient.segment<3>(3), Eigen::Vector3d::Zero());
  expect_central_differences(planes, x, gradient, 1e-7, 1e-6, 1e-6);
}

TEST(ContactPlanes, WithoutTheLastStepsImpulsesFrictionsNormalForceIsEstimatedAtTheFirstIterate) {
  // three particles of 2 g on a floor of mu_k 0.5 at z = 0: one resting (its weight, 2 g x g, as
  // the gradient at x_0), one its springs lift by more than its weight, one whose x_0 went 1 mm
  // below with no force on it (the force that stops it within the step, m d / h^2)
  SpringModel model = test::free_particles(3);
  model.mass.setConstant(0.002);
  const Obstacle floor = test::slope(0.0, 0.6, 0.5);
  std::vector<ContactPlane> planes(3);
  for (int p = 0; p < 3; ++p) planes[p] = {p, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
  Eigen::VectorXd first_iterate = Eigen::VectorXd::Zero(9), gradient = Eigen::VectorXd::Zero(9);
  gradient[2] = 0.002 * g;
  gradient[5] = -1.5 * 0.002 * g;
  first_iterate[8] = -0.001;
  lag_contact_friction(model, {floor}, nullptr, first_iterate, gradient, h, planes);
  EXPECT_NEAR(planes[0].friction_n, 0.5 * 0.002 * g, 1e-15);
  EXPECT_EQ(planes[1].friction_n, 0.0);
  EXPECT_NEAR(planes[2].friction_n, 0.5 * 0.002 * 0.001 / (h * h), 1e-15);
  // the last step's impulses, when given, set it alone: lambda = m J / h
  const Eigen::MatrixXd impulse_m_per_s = Eigen::MatrixXd::Constant(1, 3, 0.1);
  lag_contact_friction(model, {floor}, &impulse_m_per_s, first_iterate, gradient, h, planes);
  for (const ContactPlane& plane : planes) {
    EXPECT_NEAR(plane.friction_n, 0.5 * 0.002 * 0.1 / h, 1e-15);
    EXPECT_DOUBLE_EQ(plane.slip_scale_m, friction_slip_speed_m_per_s * h);
  }
}

TEST(ContactPlanes, FrictionsGradientIsItsEnergysDerivativeOnTheRampAndBeyond) {
  // F f0(|P (x - start)|) with e = 1 mm: particle 0 slips 0.5 mm (on the smoothed ramp), particle
  // 1 slips 5 mm (at the bound); the normal offset changes nothing
  std::vector<ContactPlane> planes(2);
  for (int p = 0; p < 2; ++p) {
    planes[p].particle = p;
    planes[p].normal = Eigen::Vector3d(0.0, 0.6, 0.8);
    planes[p].point = Eigen::Vector3d(0.0, 0.0, -1.0);  // far below: no penalty
    planes[p].start = Eigen::Vector3d(p, 0.0, 0.0);
    planes[p].friction_n = 0.3;
    planes[p].slip_scale_m = 1e-3;
  }
  Eigen::VectorXd x(6);
  x << 0.0003, 0.0004 * 0.8 + 0.002 * 0.6, -0.0004 * 0.6 + 0.002 * 0.8, 1.003, 0.004 * 0.8,
      -0.004 * 0.6;
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(6);
  add_contact_potential(planes, x, &gradient);
  EXPECT_NEAR(contact_slip_m(planes[0], x.head<3>()).norm(), 5e-4, 1e-12);
  EXPECT_NEAR(gradient.tail<3>().norm(), 0.3, 1e-12) << "at the bound: F";
  EXPECT_LT(gradient.head<3>().norm(), 0.3) << "on the ramp: less";
  EXPECT_NEAR(gradient.head<3>().dot(planes[0].normal), 0.0, 1e-12);
  expect_central_differences(planes, x, gradient, 1e-8, 1e-6, 0.0);
}

class Minimisers : public ::testing::TestWithParam<Integrator> {};

TEST_P(Minimisers, AFallingParticleIsStoppedInsideTheStepAsThePenaltySays) {
  // The step minimises m/(2h^2) |x - y|^2 + k/2 depth^2 with k = beta m/h^2: a particle whose
  // inertial target y lies D below the plane ends D / (1 + beta) below it.
  Obstacle floor;
  floor.thickness_m = 0.004;
  State state;
  const Eigen::Vector3d v(0.0, 0.0, -1.0);
  const SpringModel model = test::lone_particle({0.0, 0.0, 0.01}, v, state);
  const SolverParams params = minimiser_params(GetParam(), floor);
  const double target_z = 0.01 + h * v.z() - g * h * h;
  const double expected_z = floor.thickness_m - (floor.thickness_m - target_z) / (1.0 + penalty);
  StepWorkspace workspace;
  ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
  // the projection after the step then lifts it by that depth and stops it
  EXPECT_NEAR(state.x.z(), floor.thickness_m, 1e-12);
  EXPECT_NEAR(state.v.z(), 0.0, 1e-12);
  ASSERT_EQ(workspace.obstacle_penalty_impulse.cols(), 1);
  EXPECT_NEAR(workspace.obstacle_penalty_impulse(0, 0),
              penalty * (floor.thickness_m - expected_z) / h, 1e-6);
}

TEST_P(Minimisers, StaticFrictionHoldsAParticleOnASlopeAtOneStepPerFrame) {
  // tan 20 deg = 0.36 < mu_s = 0.5. The penalty stops the particle's fall inside the step, so
  // the projection after it removes only the penalty's depth, 1/(1 + beta) of the normal impulse:
  // friction must be bounded by the penalty's impulse too, or the particle slides (as the drape
  // slid off its ball before the impulse was passed on).
  // With friction in the step too, it creeps there (smoothed, with a lagged normal force) and
  // friction after the step holds it.
  const Obstacle plane = test::slope(20.0 * M_PI / 180.0, 0.5, 0.4);
  const Eigen::Vector3d start = plane.thickness_m * plane.normal;
  for (const bool in_step : {false, true}) {
    State state;
    const SpringModel model = test::lone_particle(start, Eigen::Vector3d::Zero(), state);
    SolverParams params = minimiser_params(GetParam(), plane);
    params.friction_in_step = in_step;
    // Held, the particle's normal momentum does not change: the penalty's impulses and the
    // projection's (beta times smaller) add up to gravity's normal impulse, step by step to the
    // solver's tolerance, over the 3 s to 2 %; with friction in the step to 5 %: quasi-Newton's
    // V-cycle then carries friction's stiffness in all three directions, and its steps stop up to
    // its tolerance short of the penalty's depth (the projection gives the rest).
    StepWorkspace workspace;
    double penalty_impulses_m_per_s = 0.0;
    for (int n = 0; n < 90; ++n) {
      ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
      penalty_impulses_m_per_s += workspace.obstacle_penalty_impulse(0, 0);
    }
    EXPECT_LT((state.x - start).norm(), 1e-12) << "held for 3 s; in step " << in_step;
    const double normal_impulse_m_per_s = g * std::cos(20.0 * M_PI / 180.0) * h;
    EXPECT_NEAR(penalty_impulses_m_per_s / 90.0, normal_impulse_m_per_s * penalty / (1.0 + penalty),
                (in_step ? 0.05 : 0.02) * normal_impulse_m_per_s)
        << "in step " << in_step;
  }
}

TEST_P(Minimisers, KineticFrictionSlowsASlidingParticleAsCoulombSaysAtOneStepPerFrame) {
  // down a 30-degree slope with mu_k = 0.3: a = g (sin 30 - 0.3 cos 30) = 2.36 m/s^2 along it,
  // to the penalty's 1/(1 + beta) of the normal force
  const double angle_rad = 30.0 * M_PI / 180.0;
  const Obstacle plane = test::slope(angle_rad, 0.3, 0.3);
  const Eigen::Vector3d down_slope(0.0, -std::cos(angle_rad), -std::sin(angle_rad));
  // in the step, the first step's normal force estimated (no last step): the particle starts at
  // rest, where friction's stiffness 2F/e is at its largest, and Newton's small first correction
  // is not convergence (newton.gradient_reduction; with the correction test alone it stayed put)
  for (const bool in_step : {false, true}) {
    State state;
    const SpringModel model =
        test::lone_particle(plane.thickness_m * plane.normal, Eigen::Vector3d::Zero(), state);
    SolverParams params = minimiser_params(GetParam(), plane);
    params.friction_in_step = in_step;
    StepWorkspace workspace;
    for (int n = 0; n < 30; ++n) ASSERT_EQ(step(model, params, state, workspace), StepStatus::ok);
    const double a = g * (std::sin(angle_rad) - 0.3 * std::cos(angle_rad));
    EXPECT_NEAR(state.v.dot(down_slope), a, 0.02 * a) << "in step " << in_step;
    EXPECT_NEAR(state.x.dot(plane.normal), plane.thickness_m, 1e-12) << "in step " << in_step;
  }
}

TEST_P(Minimisers, FloorFrictionDoesNotHoldAStretchedSeamOfAStiffCloth) {
  // a 0.2 kg/m^2 cloth of 1000 N/m springs lying on a floor (mu 0.6 / 0.5), its right half pulled
  // 30 % of a cell away from its left: the seam's springs pull with newtons, friction can hold
  // its weight's 0.6 mN per particle. Friction after the step alone, on the velocity, held the seam
  // open: the step moves each seam particle only to where its springs balance, a third of the
  // gap, less than mu_s g h^2 (5.9 mm at h = 1/30 s). Friction in the step bounds the force.
  constexpr int side = 11;
  constexpr double spacing_m = 0.025;
  constexpr double gap_m = 0.3 * spacing_m;
  State state;
  const SpringModel model =
      test::grid_model(side, side, spacing_m, 0.2 * spacing_m * spacing_m, 1000.0, 0.5, state);
  Obstacle floor = test::slope(0.0, 0.6, 0.5);
  floor.thickness_m = 0.004;
  for (int p = 0; p < model.particle_count(); ++p) {
    state.x(3 * p + 2) = floor.thickness_m;
    if (p % side > side / 2) state.x(3 * p) += gap_m;
  }
  const auto seam_gap_m = [&](const State& s) {
    double widest = 0.0;
    for (int row = 0; row < side; ++row) {
      const int left = row * side + side / 2;
      widest = std::max(
          widest, (s.x.segment<3>(3 * (left + 1)) - s.x.segment<3>(3 * left)).norm() - spacing_m);
    }
    return widest;
  };
  ASSERT_NEAR(seam_gap_m(state), gap_m, 1e-12);
  SolverParams params = minimiser_params(GetParam(), floor);
  params.friction_in_step = true;
  const State released = state;
  // with the last step's normal forces, and with none: every step on a model finalized anew, as
  // after a remesh every few steps, so that the friction's normal force is estimated each time
  for (const bool remeshed : {false, true}) {
    state = released;
    SpringModel stepped = model;
    StepWorkspace workspace;
    for (int n = 0; n < 30; ++n) {
      if (remeshed) finalize_model(stepped);
      ASSERT_EQ(step(stepped, params, state, workspace), StepStatus::ok);
    }
    EXPECT_LT(seam_gap_m(state), 0.05 * gap_m) << "after 1 s; remeshed " << remeshed;
    for (int p = 0; p < model.particle_count(); ++p) {
      EXPECT_NEAR(state.x(3 * p + 2), floor.thickness_m, 1e-9)
          << "particle " << p << "; remeshed " << remeshed;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, Minimisers,
                         ::testing::Values(Integrator::newton, Integrator::quasi_newton),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace tissu
