// Vertex-triangle and edge-edge crossings during a step, and closeness at its end.

#include "solver/collision/continuous_collision.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "solver/collision/primitive_distance.hpp"

namespace tissu {
namespace {

/// A vertex moving by `d` from `p`, against the still triangle (0,0,0), (1,0,0), (0,1,0).
PairMotion vertex_over_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& d) {
  PairMotion m;
  m.start = {p, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  m.displacement = {d, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  return m;
}

const CandidatePair vertex_triangle{{0, 1, 2, 3}, false};
const CandidatePair edge_edge{{0, 1, 2, 3}, true};

TEST(FirstImpact, AVertexFallingThroughATriangleHitsItWhereAndWhenItCrosses) {
  const PairMotion m = vertex_over_triangle({0.2, 0.3, 0.4}, {0.0, 0.0, -1.0});
  const std::optional<ContactPair> hit = first_impact(vertex_triangle, m, 1e-9);
  ASSERT_TRUE(hit.has_value());
  EXPECT_TRUE(hit->weight.isApprox(Eigen::Vector4d(1.0, -0.5, -0.2, -0.3)));
  EXPECT_TRUE(hit->normal.isApprox(Eigen::Vector3d::UnitZ()));  // towards where it came from
}

TEST(FirstImpact, AVertexPassingBesideATriangleOrStoppingShortDoesNot) {
  EXPECT_FALSE(
      first_impact(vertex_triangle, vertex_over_triangle({0.8, 0.8, 0.4}, {0.0, 0.0, -1.0}), 1e-9));
  EXPECT_FALSE(
      first_impact(vertex_triangle, vertex_over_triangle({0.2, 0.3, 0.4}, {0.0, 0.0, -0.3}), 1e-9));
}

TEST(FirstImpact, TwoEdgesSweepingThroughEachOtherMeet) {
  // an edge along x at z = 0, another along y falling from z = 0.5 to z = -0.5
  PairMotion m;
  m.start = {Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.25, -1, 0.5),
             Eigen::Vector3d(0.25, 1, 0.5)};
  m.displacement = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, -1),
                    Eigen::Vector3d(0, 0, -1)};
  const std::optional<ContactPair> hit = first_impact(edge_edge, m, 1e-9);
  ASSERT_TRUE(hit.has_value());
  EXPECT_TRUE(hit->weight.isApprox(Eigen::Vector4d(0.375, 0.625, -0.5, -0.5)));
  EXPECT_TRUE(hit->normal.isApprox(-Eigen::Vector3d::UnitZ()));  // the first edge started below

  m.start[2].x() = m.start[3].x() = 1.5;  // now it falls beyond the end of the first edge
  EXPECT_FALSE(first_impact(edge_edge, m, 1e-9));
}

TEST(CubicSignFilter, RulesOutOnlyCubicsThatKeepTheirSignOnTheUnitInterval) {
  // the filter may pass a cubic without roots on [0, 1] to the root finder, never the reverse: a
  // cubic it rules out must keep its sign at every sample of [0, 1]
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  int ruled_out = 0;
  for (int k = 0; k < 20000; ++k) {
    const double c3 = coefficient(random), c2 = coefficient(random), c1 = coefficient(random),
                 c0 = coefficient(random);
    if (!cubic_keeps_its_sign_on_unit_interval(c3, c2, c1, c0)) continue;
    ++ruled_out;
    for (int s = 0; s <= 1000; ++s) {
      const double t = s / 1000.0;
      ASSERT_GT((((c3 * t + c2) * t + c1) * t + c0) * c0, 0.0) << "k " << k << " t " << t;
    }
  }
  EXPECT_GT(ruled_out, 5000);  // it does rule out most of them, or it would save nothing
  // a cubic with a root inside, one with a root at the start, and one touching zero at t = 1/2
  EXPECT_FALSE(cubic_keeps_its_sign_on_unit_interval(0.0, 0.0, 1.0, -0.5));
  EXPECT_FALSE(cubic_keeps_its_sign_on_unit_interval(1.0, 1.0, 1.0, 0.0));
  EXPECT_FALSE(cubic_keeps_its_sign_on_unit_interval(0.0, 1.0, -1.0, 0.25));
}

/// The distance between the pair's primitives at time t, by the primitives' nearest points.
double distance_at(const CandidatePair& pair, const PairMotion& m, double t) {
  if (pair.edge_edge) {
    const Eigen::Vector2d st =
        nearest_between_segments(m.at(0, t), m.at(1, t), m.at(2, t), m.at(3, t));
    return ((m.at(0, t) + st[0] * (m.at(1, t) - m.at(0, t))) -
            (m.at(2, t) + st[1] * (m.at(3, t) - m.at(2, t))))
        .norm();
  }
  const Eigen::Vector3d l = nearest_on_triangle(m.at(0, t), m.at(1, t), m.at(2, t), m.at(3, t));
  return (m.at(0, t) - l[0] * m.at(1, t) - l[1] * m.at(2, t) - l[2] * m.at(3, t)).norm();
}

TEST(StaysFartherThan, RulesOutOnlyPairsThatNeverComeThatClose) {
  // random pairs in a 10 cm box moving by up to 3 cm: a pair ruled out must stay farther apart
  // than the distance at every sample of the step, and most far pairs are ruled out
  std::mt19937 random(5);
  std::uniform_real_distribution<double> position(-0.05, 0.05), move(-0.03, 0.03);
  const double distance_m = 0.004;
  int ruled_out = 0;
  for (int k = 0; k < 4000; ++k) {
    const CandidatePair& pair = k % 2 == 0 ? vertex_triangle : edge_edge;
    PairMotion m;
    for (int c = 0; c < 4; ++c) {
      m.start[c] = {position(random), position(random), position(random)};
      m.displacement[c] = {move(random), move(random), move(random)};
    }
    if (!stays_farther_than(pair, m, distance_m)) continue;
    ++ruled_out;
    for (int s = 0; s <= 200; ++s) {
      ASSERT_GT(distance_at(pair, m, s / 200.0), distance_m) << "pair " << k << " t " << s / 200.0;
    }
  }
  EXPECT_GT(ruled_out, 500);
  // two coplanar neighbours of a flat sheet drifting together: a vertex 1.8 cm from a triangle
  const PairMotion drifting = vertex_over_triangle({-0.018, 0.1, 0.0}, {0.002, 0.0, 0.0});
  EXPECT_TRUE(stays_farther_than(vertex_triangle, drifting, distance_m));
  EXPECT_FALSE(first_impact(vertex_triangle, drifting, 1e-9));
  // the vertex falling through the triangle is not ruled out
  EXPECT_FALSE(stays_farther_than(vertex_triangle,
                                  vertex_over_triangle({0.2, 0.3, 0.4}, {0.0, 0.0, -1.0}), 1e-9));
}

TEST(StaysFartherThan, RulesOutFromAnEndDistanceKnownBeforeTheCornersMoved) {
  // self-collision's step 2 reuses step 1's distances at the end of the step after step 1 has
  // moved some corners: the distance before, less the farthest a corner of each primitive moved,
  // bounds the distance after from below. Random pairs in a 3 cm box whose primitives move apart
  // rigidly by up to 2 cm, after which some of their corners are pulled back part of the way
  // (what step 1 does to a pair it finds too close), or moved at random.
  std::mt19937 random(8);
  std::uniform_real_distribution<double> position(-0.015, 0.015), move(-0.02, 0.02), unit(0.0, 1.0);
  const double distance_m = 0.004;
  int ruled_out = 0;
  for (int k = 0; k < 4000; ++k) {
    const CandidatePair& pair = k % 2 == 0 ? vertex_triangle : edge_edge;
    const int first_size = pair.first_primitive_size();
    const std::array<Eigen::Vector3d, 2> apart = {
        Eigen::Vector3d(move(random), move(random), move(random)),
        Eigen::Vector3d(move(random), move(random), move(random))};
    PairMotion m;
    for (int c = 0; c < 4; ++c) {
      m.start[c] = {position(random), position(random), position(random)};
      m.displacement[c] = apart[c < first_size ? 0 : 1];
    }
    const double end_distance_m = proximity_at_end(pair, m, distance_m).distance_m;
    double first_moved_m = 0.0, second_moved_m = 0.0;
    for (int c = 0; c < 4; ++c) {
      if (unit(random) < 0.3) continue;  // this corner stays
      const Eigen::Vector3d d = k % 4 < 2
                                    ? Eigen::Vector3d(-unit(random) * m.displacement[c])
                                    : Eigen::Vector3d(move(random), move(random), move(random));
      m.displacement[c] += d;
      double& moved_m = c < first_size ? first_moved_m : second_moved_m;
      moved_m = std::max(moved_m, d.norm());
    }
    if (!stays_farther_than(pair, m, distance_m, end_distance_m - first_moved_m - second_moved_m))
      continue;
    ++ruled_out;
    for (int s = 0; s <= 200; ++s) {
      ASSERT_GT(distance_at(pair, m, s / 200.0), distance_m) << "pair " << k << " t " << s / 200.0;
    }
  }
  EXPECT_GT(ruled_out, 40);
}

TEST(ProximityAtEnd, FindsPairsWithinTheThicknessOnly) {
  const PairMotion m = vertex_over_triangle({0.2, 0.3, 0.5}, {0.0, 0.0, -0.497});
  const EndProximity close = proximity_at_end(vertex_triangle, m, 0.004);
  EXPECT_NEAR(close.distance_m, 0.003, 1e-12);
  ASSERT_TRUE(close.contact.has_value());
  EXPECT_NEAR(close.contact->distance_m, 0.003, 1e-12);
  EXPECT_TRUE(close.contact->normal.isApprox(Eigen::Vector3d::UnitZ()));
  const EndProximity apart = proximity_at_end(vertex_triangle, m, 0.002);
  EXPECT_NEAR(apart.distance_m, 0.003, 1e-12);
  EXPECT_FALSE(apart.contact);
}

}  // namespace
}  // namespace tissu
