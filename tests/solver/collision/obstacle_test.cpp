// Signed distances and motion of the analytic obstacles.

#include "solver/collision/obstacle.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace tissu {
namespace {

void expect_surface(const Obstacle& o, const Eigen::Vector3d& x, double distance_m,
                    const Eigen::Vector3d& normal, double time_s = 0.0) {
  const SurfaceDistance s = surface_distance(o, x, time_s);
  EXPECT_NEAR(s.distance_m, distance_m, 1e-12) << "at " << x.transpose();
  EXPECT_TRUE(s.normal.isApprox(normal, 1e-12)) << s.normal.transpose() << " at " << x.transpose();
}

TEST(ObstacleDistance, PlaneIsSignedAlongItsNormal) {
  Obstacle floor;
  floor.position = {0.0, 0.0, -1.0};
  floor.normal = Eigen::Vector3d(0.0, 1.0, 1.0).normalized();
  expect_surface(floor, {5.0, 0.0, -1.0}, 0.0, floor.normal);
  expect_surface(floor, {0.0, 0.0, -3.0}, -2.0 / std::sqrt(2.0), floor.normal);
}

TEST(ObstacleDistance, SphereAndCapsuleMeasureFromTheirCore) {
  Obstacle ball;
  ball.shape = ObstacleShape::sphere;
  ball.position = {1.0, 2.0, 3.0};
  ball.radius_m = 0.5;
  expect_surface(ball, {1.0, 2.0, 5.0}, 1.5, Eigen::Vector3d::UnitZ());
  expect_surface(ball, {1.0, 1.8, 3.0}, -0.3, -Eigen::Vector3d::UnitY());

  Obstacle rod;
  rod.shape = ObstacleShape::capsule;
  rod.position = {0.0, 0.0, 0.0};
  rod.axis_end = {2.0, 0.0, 0.0};
  rod.radius_m = 0.1;
  expect_surface(rod, {1.3, 0.0, 0.4}, 0.3, Eigen::Vector3d::UnitZ());       // beside the axis
  expect_surface(rod, {3.0, 0.0, 0.0}, 0.9, Eigen::Vector3d::UnitX());       // beyond an end
  expect_surface(rod, {-0.05, 0.0, 0.0}, -0.05, -Eigen::Vector3d::UnitX());  // inside a cap
}

TEST(ObstacleDistance, BoxMeasuresToFacesEdgesAndCornersAndRotates) {
  Obstacle box;
  box.shape = ObstacleShape::box;
  box.half_extents_m = {1.0, 2.0, 3.0};
  expect_surface(box, {1.5, 0.0, 0.0}, 0.5, Eigen::Vector3d::UnitX());  // facing a face
  expect_surface(box, {2.0, 3.0, 0.0}, std::sqrt(2.0), Eigen::Vector3d(1, 1, 0).normalized());
  expect_surface(box, {-2.0, -3.0, -4.0}, std::sqrt(3.0), -Eigen::Vector3d::Ones().normalized());
  expect_surface(box, {0.0, 1.9, 0.0}, -0.1, Eigen::Vector3d::UnitY());  // inside, near +y

  // turned 90 degrees about z: its 1 m half extent now lies along y
  box.rotation = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  expect_surface(box, {0.0, 1.5, 0.0}, 0.5, Eigen::Vector3d::UnitY());
  expect_surface(box, {2.5, 0.0, 0.0}, 0.5, Eigen::Vector3d::UnitX());
}

TEST(ObstacleMotion, FollowsKeyframesLinearlyAndDrifts) {
  RigidMotion m;
  m.keys = {{1.0, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d::Zero()},
            {3.0, Eigen::Vector3d(0, 0, -2), Eigen::Vector3d::Zero()}};
  m.drift_m_per_s = {0.5, 0.0, 0.0};
  const auto offset = [&m](double t) { return m.pose(t).translation_m; };
  EXPECT_TRUE(offset(0.0).isApprox(Eigen::Vector3d(0, 0, 0)));  // held before the first key
  EXPECT_TRUE(offset(2.0).isApprox(Eigen::Vector3d(1.0, 0, -1)));
  EXPECT_TRUE(offset(5.0).isApprox(Eigen::Vector3d(2.5, 0, -2)));  // held after the last
  EXPECT_TRUE(m.point_velocity({0, 0, 0}, 2.0).isApprox(Eigen::Vector3d(0.5, 0, -1)));
  EXPECT_TRUE(m.point_velocity({0, 0, 0}, 4.0).isApprox(Eigen::Vector3d(0.5, 0, 0)));

  Obstacle ball;
  ball.shape = ObstacleShape::sphere;
  ball.radius_m = 1.0;
  ball.motion = m;
  expect_surface(ball, {1.0, 0.0, -1.0}, -1.0, Eigen::Vector3d::UnitZ(), 2.0);  // centre moved
}

TEST(ObstacleMotion, ARotatingObstacleTurnsItsSurfaceAndNormals) {
  // a 2 x 0.2 x 2 m slab centred at the origin turns a quarter about z in 1 s, pivot at its centre
  Obstacle slab;
  slab.shape = ObstacleShape::box;
  slab.half_extents_m = {1.0, 0.1, 1.0};
  slab.motion.keys = {{0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                      {1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, M_PI / 2)}};
  expect_surface(slab, {0.0, 0.5, 0.0}, 0.4, Eigen::Vector3d::UnitY(), 0.0);
  // a quarter turn later its thin side faces -x and +x
  expect_surface(slab, {0.5, 0.0, 0.0}, 0.4, Eigen::Vector3d::UnitX(), 1.0);
  expect_surface(slab, {0.0, 1.5, 0.0}, 0.5, Eigen::Vector3d::UnitY(), 1.0);
  // half way, the point 1 m out along the slab moves at omega r = pi/2 m/s, tangentially
  const Eigen::Vector3d tip = slab.motion.pose(0.5).apply({1.0, 0.0, 0.0});
  const Eigen::Vector3d v = slab.motion.point_velocity(tip, 0.5);
  EXPECT_NEAR(v.norm(), M_PI / 2, 1e-12);
  EXPECT_NEAR(v.dot(tip), 0.0, 1e-12);
}

}  // namespace
}  // namespace tissu
