// The generalised winding number: exact solid angles, and the hierarchical sum against them.

#include "topology/winding_number.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "tests/test_meshes.hpp"

namespace tissu {
namespace {

std::vector<Eigen::Vector3d> corners(const IndexedMesh& mesh) {
  std::vector<Eigen::Vector3d> out;
  for (const std::vector<int>& f : mesh.faces) {
    for (int v : f) out.push_back(mesh.vertices[v]);
  }
  return out;
}

/// A UV sphere of `n` meridians and n / 2 bands around the origin, facing outwards, as a soup.
std::vector<Eigen::Vector3d> sphere_corners(double radius_m, int n) {
  const auto point = [&](int band, int meridian) {
    const double phi = std::numbers::pi * band / (n / 2),
                 theta = 2 * std::numbers::pi * meridian / n;
    return Eigen::Vector3d(radius_m * std::sin(phi) * std::cos(theta),
                           radius_m * std::sin(phi) * std::sin(theta), radius_m * std::cos(phi));
  };
  std::vector<Eigen::Vector3d> out;
  for (int b = 0; b < n / 2; ++b) {
    for (int m = 0; m < n; ++m) {
      const Eigen::Vector3d p = point(b, m), q = point(b + 1, m), r = point(b + 1, m + 1),
                            s = point(b, m + 1);
      // counter-clockwise seen from outside: down the meridian, then east
      if (b > 0) out.insert(out.end(), {p, q, s});
      if (b + 1 < n / 2) out.insert(out.end(), {q, r, s});
    }
  }
  return out;
}

TEST(SolidAngle, OfATriangleSeenFromItsBackIsPositive) {
  const Eigen::Vector3d a(0, 0, 1), b(1, 0, 1), c(0, 1, 1);  // faces +z
  EXPECT_GT(solid_angle_sr(a, b, c, Eigen::Vector3d::Zero()), 0.0);
  EXPECT_LT(solid_angle_sr(a, b, c, Eigen::Vector3d(0, 0, 2)), 0.0);
  // a quarter of the plane seen from just behind its corner: a quarter of a hemisphere
  const double big = 1e6;
  EXPECT_NEAR(solid_angle_sr({0, 0, 0}, {big, 0, 0}, {0, big, 0}, {0, 0, -1e-3}),
              std::numbers::pi / 2.0, 1e-6);
}

TEST(WindingNumber, IsOneInsideAClosedCubeAndZeroOutside) {
  const WindingNumberTree tree(corners(test::cube_mesh(Eigen::Vector3d::Zero(), 1.0)));
  EXPECT_NEAR(tree.exact_winding_number({0.1, -0.3, 0.9}), 1.0, 1e-12);
  EXPECT_NEAR(tree.exact_winding_number({0.1, -0.3, 1.1}), 0.0, 1e-12);
  EXPECT_NEAR(tree.exact_winding_number({5.0, 4.0, -3.0}), 0.0, 1e-12);
}

TEST(WindingNumber, CountsOverlappingParts) {
  std::vector<Eigen::Vector3d> soup = corners(test::cube_mesh(Eigen::Vector3d::Zero(), 1.0));
  const std::vector<Eigen::Vector3d> other = corners(test::cube_mesh({1.0, 0.0, 0.0}, 1.0));
  soup.insert(soup.end(), other.begin(), other.end());
  const WindingNumberTree tree(soup);
  EXPECT_NEAR(tree.exact_winding_number({0.5, 0.0, 0.0}), 2.0, 1e-12);
  EXPECT_NEAR(tree.exact_winding_number({-0.5, 0.0, 0.0}), 1.0, 1e-12);
  EXPECT_NEAR(tree.exact_winding_number({1.5, 0.0, 0.0}), 1.0, 1e-12);
}

TEST(WindingNumber, TheHierarchicalSumStaysCloseToTheExactOne) {
  const WindingNumberTree tree(sphere_corners(1.0, 96));  // 9,024 triangles
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  double worst = 0.0;
  for (int n = 0; n < 400; ++n) {
    const Eigen::Vector3d x(coordinate(random), coordinate(random), coordinate(random));
    const double exact = tree.exact_winding_number(x);
    worst = std::max(worst, std::abs(tree.winding_number(x) - exact));
    // the faceted sphere lies within 1e-3 of the round one: test away from that band
    if (std::abs(x.norm() - 1.0) > 1e-2) {
      EXPECT_NEAR(exact, x.norm() < 1.0 ? 1.0 : 0.0, 1e-9);
    }
  }
  EXPECT_LT(worst, 0.05);  // the inside test needs < 0.5
  // near the surface the tree opens down to the exact triangles
  for (double r : {0.99, 0.999, 1.001, 1.01}) {
    const Eigen::Vector3d x = r * Eigen::Vector3d(0.3, -0.5, 0.81).normalized();
    EXPECT_NEAR(tree.winding_number(x), r < 1.0 ? 1.0 : 0.0, 0.05) << r;
  }
}

TEST(WindingNumber, OfAnEmptySoupIsZero) {
  EXPECT_EQ(WindingNumberTree({}).winding_number(Eigen::Vector3d::Zero()), 0.0);
}

}  // namespace
}  // namespace tissu
