#include "solver/forces/aerodynamic_force.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tissu {
namespace {

const Eigen::Vector3d a(0.0, 0.0, 0.0);
const Eigen::Vector3d b(2.0, 0.0, 0.0);
const Eigen::Vector3d c(0.0, 1.0, 0.0);  // area 1 m^2, normal +z
const Eigen::Vector3d still = Eigen::Vector3d::Zero();

TEST(AerodynamicForce, FlowFacingTheTriangleGivesRayleighDrag) {
  const double rho = 1.2;
  const double drag = 1.1;
  const Eigen::Vector3d wind(0.0, 0.0, 5.0);
  const Eigen::Vector3d force =
      triangle_aerodynamic_force(a, b, c, still, still, still, wind, rho, drag);
  const Eigen::Vector3d expected(0.0, 0.0, 0.5 * rho * drag * 1.0 * 25.0);
  EXPECT_LT((force - expected).norm(), 1e-12);
  // against the normal it pushes the other way, whatever the winding of the triangle
  const Eigen::Vector3d reversed =
      triangle_aerodynamic_force(a, c, b, still, still, still, -wind, rho, drag);
  EXPECT_LT((reversed + expected).norm(), 1e-12);
}

TEST(AerodynamicForce, OnlyTheNormalRelativeVelocityCounts) {
  const Eigen::Vector3d tangential(3.0, -2.0, 0.0);
  EXPECT_TRUE(
      triangle_aerodynamic_force(a, b, c, still, still, still, tangential, 1.2, 1.0).isZero());
  const Eigen::Vector3d wind(1.0, 0.0, 4.0);
  EXPECT_TRUE(triangle_aerodynamic_force(a, b, c, wind, wind, wind, wind, 1.2, 1.0).isZero());
  // a triangle moving into still air is braked
  const Eigen::Vector3d up(0.0, 0.0, 2.0);
  EXPECT_LT(triangle_aerodynamic_force(a, b, c, up, up, up, still, 1.2, 1.0).z(), 0.0);
}

TEST(AerodynamicForce, DegenerateTriangleGivesZero) {
  const Eigen::Vector3d force = triangle_aerodynamic_force(
      a, b, 2.0 * b, still, still, still, Eigen::Vector3d(0.0, 0.0, 5.0), 1.2, 1.0);
  EXPECT_TRUE(force.isZero());
  EXPECT_TRUE(force.allFinite());
}

TEST(AerodynamicForce, GustsStayWithinTheirAmplitude) {
  Wind wind;
  wind.velocity = Eigen::Vector3d(0.0, 4.0, 0.0);
  wind.gust_amplitude = 0.5;
  wind.gust_frequency = 0.7;
  double lowest = 1e9, highest = -1e9;
  for (int n = 0; n < 20000; ++n) {
    const double t = 0.001 * n;
    EXPECT_LE(std::abs(gust_signal(wind.gust_frequency, t)), 1.0);
    const double speed = wind_velocity(wind, t).y();
    lowest = std::min(lowest, speed);
    highest = std::max(highest, speed);
  }
  EXPECT_GE(lowest, 4.0 * 0.5);
  EXPECT_LE(highest, 4.0 * 1.5);
  EXPECT_GT(highest - lowest, 2.0);  // the gusts do vary the wind
  wind.gust_amplitude = 0.0;
  EXPECT_EQ(wind_velocity(wind, 3.21), wind.velocity);
}

TEST(AerodynamicForce, EachVertexGetsAThird) {
  SpringModel model;
  model.mass = Eigen::VectorXd::Constant(3, 1.0);
  model.pinned.assign(3, 0);
  model.springs.resize(0, 2);
  model.triangles.resize(1, 3);
  model.triangles << 0, 1, 2;
  finalize_model(model);
  Eigen::VectorXd x(9), v = Eigen::VectorXd::Zero(9);
  x << a, b, c;
  Wind wind;
  wind.velocity = Eigen::Vector3d(0.0, 0.0, 2.0);
  Eigen::Matrix3Xd buffer;
  Eigen::VectorXd force = Eigen::VectorXd::Zero(9);
  add_aerodynamic_forces(model, wind, 0.0, x, v, buffer, force);
  const Eigen::Vector3d total = triangle_aerodynamic_force(
      a, b, c, still, still, still, wind.velocity, wind.air_density, wind.drag_coefficient);
  for (int p = 0; p < 3; ++p) {
    EXPECT_LT((Eigen::Vector3d(force.segment<3>(3 * p)) - total / 3.0).norm(), 1e-14);
  }
}

}  // namespace
}  // namespace tissu
