// Closest points between a point and a triangle and between two segments.

#include "solver/collision/primitive_distance.hpp"

#include <gtest/gtest.h>

namespace tissu {
namespace {

const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);

TEST(NearestOnTriangle, ProjectsInsideAndClampsToEdgesAndCorners) {
  EXPECT_TRUE(
      nearest_on_triangle({0.5, 0.5, 3.0}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.25, 0.25)));
  EXPECT_TRUE(
      nearest_on_triangle({1.0, -1.0, 0.5}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0.0)));
  EXPECT_TRUE(
      nearest_on_triangle({3.0, 3.0, 0.0}, a, b, c).isApprox(Eigen::Vector3d(0.0, 0.5, 0.5)));
  EXPECT_TRUE(
      nearest_on_triangle({-1.0, -1.0, 0.0}, a, b, c).isApprox(Eigen::Vector3d(1.0, 0.0, 0.0)));
  // a degenerate (flat) triangle still gives its nearest edge point
  const Eigen::Vector3d l = nearest_on_triangle({1.0, 1.0, 0.0}, a, b, Eigen::Vector3d(1, 0, 0));
  EXPECT_NEAR(l.sum(), 1.0, 1e-12);
  EXPECT_TRUE(
      (l[0] * a + l[1] * b + l[2] * Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(1, 0, 0)));
}

TEST(NearestBetweenSegments, HandlesCrossingSkewEndAndParallelCases) {
  // skew, crossing above each other at their middles
  EXPECT_TRUE(nearest_between_segments({-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1})
                  .isApprox(Eigen::Vector2d(0.5, 0.5)));
  // the closest point of the second is past the end of the first
  EXPECT_TRUE(nearest_between_segments({0, 0, 0}, {1, 0, 0}, {2, -1, 0}, {2, 1, 0})
                  .isApprox(Eigen::Vector2d(1.0, 0.5)));
  // parallel: any pair of closest points will do, as long as they are at the true distance
  const Eigen::Vector2d st =
      nearest_between_segments({0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {1.5, 1, 0});
  const Eigen::Vector3d p = Eigen::Vector3d(st[0], 0, 0), q = Eigen::Vector3d(0.5 + st[1], 1, 0);
  EXPECT_NEAR((p - q).norm(), 1.0, 1e-12);
}

}  // namespace
}  // namespace tissu
