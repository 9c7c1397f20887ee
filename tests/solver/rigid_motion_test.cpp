// Keyframed rigid motions: exact at their keys, continuous between, C1 when smooth, and their
// velocities the derivatives of their positions.

#include "solver/rigid_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tissu {
namespace {

constexpr double pi = std::numbers::pi;

/// Three keys: a translation out and back up, and a quarter then a full turn about z.
RigidMotion three_keys(KeyInterpolation interpolation) {
  RigidMotion motion;
  motion.interpolation = interpolation;
  motion.pivot_m = {1.0, 0.0, 0.0};
  motion.keys = {{0.5, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
                 {1.5, {2.0, 0.0, 0.0}, {0.0, 0.0, pi / 2}},
                 {2.0, {2.0, 0.0, 1.0}, {0.0, 0.0, 2 * pi}}};
  return motion;
}

TEST(RigidMotion, ExactAtItsKeysAndHeldOutsideThem) {
  for (KeyInterpolation interpolation : {KeyInterpolation::linear, KeyInterpolation::smooth}) {
    const RigidMotion motion = three_keys(interpolation);
    const Eigen::Vector3d x{2.0, 0.0, 0.0};                     // 1 m from the pivot along x
    EXPECT_TRUE(motion.pose(0.0).apply(x).isApprox(x, 1e-15));  // before the first key
    EXPECT_TRUE(motion.pose(0.5).apply(x).isApprox(x, 1e-15));
    // a quarter turn about the pivot (1, 0, 0) takes x to (1, 1, 0), then 2 m along x
    EXPECT_NEAR((motion.pose(1.5).apply(x) - Eigen::Vector3d(3.0, 1.0, 0.0)).norm(), 0.0, 1e-14);
    // a whole turn: back along x, 2 m on and 1 m up; held after the last key
    for (double t : {2.0, 3.0}) {
      EXPECT_NEAR((motion.pose(t).apply(x) - Eigen::Vector3d(4.0, 0.0, 1.0)).norm(), 0.0, 1e-14);
      EXPECT_TRUE(motion.point_velocity(motion.pose(t).apply(x), t + 0.1).isZero());
    }
  }
}

TEST(RigidMotion, PositionsAreContinuousAndVelocitiesTheirDerivatives) {
  for (KeyInterpolation interpolation : {KeyInterpolation::linear, KeyInterpolation::smooth}) {
    RigidMotion motion = three_keys(interpolation);
    motion.drift_m_per_s = {0.0, 0.1, 0.0};
    const Eigen::Vector3d x0{2.0, 0.5, -0.3};
    constexpr double dt = 1e-6;
    for (double t = 0.0; t < 2.5; t += 0.01) {
      const Eigen::Vector3d x = motion.pose(t).apply(x0);
      const Eigen::Vector3d later = motion.pose(t + dt).apply(x0);
      EXPECT_LT((later - x).norm(), 1e-4) << "jump at t = " << t;
      // away from the keys, where a linear velocity jumps and a smooth one's rate of change does
      if (std::abs(std::remainder(t, 0.5)) < 2 * dt) continue;
      const Eigen::Vector3d earlier = motion.pose(t - dt).apply(x0);
      const Eigen::Vector3d central = (later - earlier) / (2 * dt);
      EXPECT_LT((motion.point_velocity(x, t) - central).norm(), 1e-5 * (1.0 + central.norm()))
          << "t = " << t;
    }
  }
}

TEST(RigidMotion, SmoothKeysMoveWithoutAJumpInVelocity) {
  const RigidMotion motion = three_keys(KeyInterpolation::smooth);
  const Eigen::Vector3d x0{2.0, 0.0, 0.0};
  for (double key_s : {0.5, 1.5, 2.0}) {
    const Eigen::Vector3d x = motion.pose(key_s).apply(x0);
    const Eigen::Vector3d before = motion.point_velocity(x, key_s - 1e-9);
    const Eigen::Vector3d after = motion.point_velocity(x, key_s + 1e-9);
    EXPECT_LT((before - after).norm(), 1e-6) << "key at " << key_s << " s";
  }
  // linear keys do jump: the segment from 0.5 to 1.5 s moves 2 m/s along x, the next 2 m/s up
  const RigidMotion linear = three_keys(KeyInterpolation::linear);
  const Eigen::Vector3d at_key = linear.pose(1.5).apply(x0);
  EXPECT_GT((linear.point_velocity(at_key, 1.5 - 1e-9) - linear.point_velocity(at_key, 1.5)).norm(),
            1.0);
}

TEST(RigidMotion, CarryComposesPoses) {
  const RigidMotion motion = three_keys(KeyInterpolation::smooth);
  const Eigen::Vector3d x0{1.3, -0.2, 0.4};
  const Eigen::Vector3d at_1 = motion.pose(1.0).apply(x0);
  EXPECT_NEAR((motion.carry(at_1, 1.0, 1.8) - motion.pose(1.8).apply(x0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((motion.carry(motion.carry(at_1, 1.0, 1.8), 1.8, 1.0) - at_1).norm(), 0.0, 1e-14);
}

TEST(RigidMotion, FastestSpeedBoundsEveryPointsSpeed) {
  for (KeyInterpolation interpolation : {KeyInterpolation::linear, KeyInterpolation::smooth}) {
    const RigidMotion motion = three_keys(interpolation);
    const double reach_m = 1.5;
    const double bound = motion.fastest_speed_m_per_s(reach_m);
    double fastest = 0.0;
    for (double t = 0.0; t < 2.5; t += 0.001) {
      const Eigen::Vector3d x =
          motion.pose(t).apply(motion.pivot_m + Eigen::Vector3d(0, reach_m, 0));
      fastest = std::max(fastest, motion.point_velocity(x, t).norm());
    }
    EXPECT_LE(fastest, bound * (1.0 + 1e-9));
    EXPECT_GT(fastest, 0.5 * bound);  // and is not loose
  }
}

TEST(RigidMotion, WithoutKeysItDrifts) {
  RigidMotion motion;
  EXPECT_FALSE(motion.moves());
  motion.drift_m_per_s = {0.0, 0.0, -2.0};
  EXPECT_TRUE(motion.moves());
  EXPECT_FALSE(motion.rotates());
  EXPECT_TRUE(motion.pose(1.5).apply({1, 1, 1}).isApprox(Eigen::Vector3d(1, 1, -2), 1e-15));
  EXPECT_TRUE(motion.point_velocity({5, 5, 5}, 0.3).isApprox(Eigen::Vector3d(0, 0, -2), 1e-15));
  EXPECT_DOUBLE_EQ(motion.fastest_speed_m_per_s(10.0), 2.0);
}

}  // namespace
}  // namespace tissu
