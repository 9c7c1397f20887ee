// The triangle hierarchy of mesh obstacles: nearest triangles and the triangles a segment may
// meet, at the pose it was built from and refitted to others, against every triangle checked.

#include "solver/collision/triangle_bvh.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "solver/collision/primitive_distance.hpp"

namespace tissu {
namespace {

/// `count` triangles (three corners each) of sizes from 1 mm to `largest_m` about random points of
/// the unit cube, some long and thin.
std::vector<Eigen::Vector3d> triangle_soup(int count, std::mt19937& random,
                                           double largest_m = 0.2) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> size_exponent(-3.0, std::log10(largest_m));
  std::vector<Eigen::Vector3d> corners;
  for (int t = 0; t < count; ++t) {
    const Eigen::Vector3d centre(unit(random), unit(random), unit(random));
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d offset =
          Eigen::Vector3d(unit(random), unit(random), unit(random)).array() - 0.5;
      corners.push_back(centre + std::pow(10.0, size_exponent(random)) * offset);
    }
  }
  return corners;
}

/// The smallest squared distance from x to any triangle, each checked (m²).
double nearest_of_all_m2(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& x) {
  double best_m2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < corners.size(); k += 3) {
    const Eigen::Vector3d& a = corners[k];
    const Eigen::Vector3d& b = corners[k + 1];
    const Eigen::Vector3d& c = corners[k + 2];
    const Eigen::Vector3d l = nearest_on_triangle(x, a, b, c);
    best_m2 = std::min(best_m2, (l[0] * a + l[1] * b + l[2] * c - x).squaredNorm());
  }
  return best_m2;
}

void expect_nearest_of_all(const TriangleBvh& bvh, const std::vector<Eigen::Vector3d>& corners,
                           std::mt19937& random) {
  std::uniform_real_distribution<double> around(-0.5, 1.5);
  for (int q = 0; q < 2000; ++q) {
    const Eigen::Vector3d x(around(random), around(random), around(random));
    const NearestTriangle found = bvh.nearest(x);
    ASSERT_GE(found.triangle, 0);
    ASSERT_LT(found.triangle, static_cast<int>(corners.size() / 3));
    const Eigen::Vector3d& l = found.barycentric;
    EXPECT_GE(l.minCoeff(), -1e-12);
    EXPECT_NEAR(l.sum(), 1.0, 1e-12);
    const int k = 3 * found.triangle;
    const Eigen::Vector3d on = l[0] * corners[k] + l[1] * corners[k + 1] + l[2] * corners[k + 2];
    EXPECT_NEAR((on - x).squaredNorm(), found.distance_m2, 1e-12);
    const double expected_m2 = nearest_of_all_m2(corners, x);
    EXPECT_NEAR(found.distance_m2, expected_m2, 1e-12 + 1e-9 * expected_m2) << "query " << q;
  }
}

TEST(TriangleBvh, FindsTheNearestOfAllTriangles) {
  std::mt19937 random(11);
  const std::vector<Eigen::Vector3d> corners = triangle_soup(1500, random);
  const TriangleBvh bvh(std::make_shared<const TriangleBvhShape>(corners), corners);
  expect_nearest_of_all(bvh, corners, random);
}

TEST(TriangleBvh, FindsTheNearestAtAnyPoseOfTheTrianglesItWasBuiltFrom) {
  std::mt19937 random(12);
  const std::vector<Eigen::Vector3d> built_at = triangle_soup(1500, random);
  const auto shape = std::make_shared<const TriangleBvhShape>(built_at);
  // half of the triangles turned a quarter turn about the cube's centre and pulled apart: boxes
  // built for the first pose now mix triangles from everywhere
  std::vector<Eigen::Vector3d> moved = built_at;
  const Eigen::AngleAxisd turn(M_PI / 2, Eigen::Vector3d(1, 1, 0).normalized());
  const Eigen::Vector3d centre(0.5, 0.5, 0.5);
  for (std::size_t k = 0; k < moved.size(); ++k) {
    if ((k / 3) % 2 == 0) moved[k] = centre + turn * (moved[k] - centre);
    moved[k] += 0.2 * Eigen::Vector3d(std::sin(1.7 * k), std::cos(0.3 * k), 0.0) / (1 + k % 7);
  }
  const TriangleBvh bvh(shape, moved);
  Eigen::AlignedBox3d every_corner;
  for (const Eigen::Vector3d& corner : moved) every_corner.extend(corner);
  EXPECT_TRUE(bvh.bounds().isApprox(every_corner, 0.0));  // the refitted root: the same box
  expect_nearest_of_all(bvh, moved, random);
}

/// The parameter along from->to at which it crosses triangle abc's inside, by Möller & Trumbore
/// 1997; NaN if it misses it or passes within `margin` of its edges or its ends.
double crossing_parameter(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c, double margin) {
  const Eigen::Vector3d d = to - from, e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return NAN;
  const Eigen::Vector3d s = from - a;
  const double u = s.dot(p) / det;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det, t = e2.dot(q) / det;
  if (u < margin || v < margin || u + v > 1.0 - margin || t < margin || t > 1.0 - margin) {
    return NAN;
  }
  return t;
}

TEST(TriangleBvh, VisitsEveryTriangleASegmentMeetsAndFewOthers) {
  std::mt19937 random(13);
  const std::vector<Eigen::Vector3d> built_at = triangle_soup(2000, random, 0.6);
  std::vector<Eigen::Vector3d> moved = built_at;  // a second pose: everything shifted a little
  for (std::size_t k = 0; k < moved.size(); ++k) moved[k] += 0.05 * Eigen::Vector3d(0, 0, k % 3);
  const std::vector<Eigen::Vector3d>& second_pose = moved;
  const auto shape = std::make_shared<const TriangleBvhShape>(built_at);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const std::vector<Eigen::Vector3d>* corners : {&built_at, &second_pose}) {
    const TriangleBvh bvh(shape, *corners);
    int met = 0, visited_all = 0;
    for (int s = 0; s < 1000; ++s) {
      const Eigen::Vector3d from(unit(random), unit(random), unit(random));
      // short (a ray out of a small box) to long (across the whole soup), one along an axis
      Eigen::Vector3d ray = Eigen::Vector3d(unit(random), unit(random), unit(random)).array() - 0.5;
      if (s % 10 == 0) ray = Eigen::Vector3d(0, 0, 1);
      const Eigen::Vector3d to = from + (s % 3 == 0 ? 2.0 : 0.2) * ray;
      std::set<int> visits;
      bvh.for_each_near_segment(from, to, [&visits](int t) { visits.insert(t); });
      visited_all += static_cast<int>(visits.size());
      for (int t = 0; t < static_cast<int>(corners->size() / 3); ++t) {
        const double at = crossing_parameter(from, to, (*corners)[3 * t], (*corners)[3 * t + 1],
                                             (*corners)[3 * t + 2], 1e-9);
        if (std::isnan(at)) continue;
        ++met;
        EXPECT_TRUE(visits.count(t)) << "segment " << s << " meets triangle " << t;
      }
    }
    EXPECT_GT(met, 100);  // the segments do cross triangles
    // and the hierarchy is no list of all: a fraction of the 2,000 triangles per segment
    EXPECT_LT(visited_all, 1000 * 2000 / 5);
  }
}

TEST(TriangleBvh, HandlesASingleTriangleAndSegmentsAlongItsPlane) {
  const std::vector<Eigen::Vector3d> corners{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const TriangleBvh bvh(std::make_shared<const TriangleBvhShape>(corners), corners);
  const NearestTriangle found = bvh.nearest({2.0, 2.0, 1.0});
  EXPECT_EQ(found.triangle, 0);
  EXPECT_TRUE(found.barycentric.isApprox(Eigen::Vector3d(0.0, 0.5, 0.5)));
  EXPECT_NEAR(found.distance_m2, 1.5 * 1.5 * 2 + 1.0, 1e-12);
  int visits = 0;
  // in the triangle's plane (a zero component of the direction) and through it
  bvh.for_each_near_segment({0.2, -1.0, 0.0}, {0.2, 2.0, 0.0}, [&visits](int) { ++visits; });
  EXPECT_EQ(visits, 1);
  // beside its box in that plane, and above it parallel to it
  bvh.for_each_near_segment({-0.5, -1.0, 0.0}, {-0.5, 2.0, 0.0}, [&visits](int) { ++visits; });
  bvh.for_each_near_segment({0.2, -1.0, 0.1}, {0.2, 2.0, 0.1}, [&visits](int) { ++visits; });
  EXPECT_EQ(visits, 1);
}

}  // namespace
}  // namespace tissu
