#include "topology/split_edge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "cloth_test_support.hpp"
#include "solver/forces/accumulate_forces.hpp"
#include "topology/compile.hpp"
#include "topology/edge_measures.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.3;

class SplitEdgeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    options = test::grid(6, 5, GridCells::triangles);
    pinned = test::build_grid_pinned_at_top(options, density_kg_per_m2, springs, lcc);
  }

  double expected_mass_kg() const { return density_kg_per_m2 * options.width * options.height; }

  void expect_invariants(const std::string& when) {
    test::expect_valid_with_mass(lcc, expected_mass_kg(), when);
  }

  /// Some dart of the edge whose vertices have source ids a and b, in either direction.
  Dart_handle dart_between(int a, int b) {
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
      if (lcc.vertex_attribute(d)->info().source_index == a &&
          lcc.vertex_attribute(lcc.next(d))->info().source_index == b) {
        return d;
      }
    }
    ADD_FAILURE() << "no edge " << a << " -> " << b;
    return nullptr;
  }

  GridOptions options;
  SpringSettings springs = test::all_springs();
  ClothComplex lcc;
  int pinned = 0;
};

TEST_F(SplitEdgeTest, InteriorSplitAddsOneParticleTwoFacesAndConservesMass) {
  const std::size_t vertices = lcc.vertex_attributes().size();
  const std::size_t faces = lcc.attributes<2>().size();
  const Dart_handle from_m = split_edge(lcc, dart_between(8, 9), springs);
  EXPECT_EQ(lcc.vertex_attributes().size(), vertices + 1);
  EXPECT_EQ(lcc.attributes<2>().size(), faces + 2);
  EXPECT_EQ(lcc.vertex_attribute(from_m)->info().source_index, -1);
  EXPECT_GT(lcc.vertex_attribute(from_m)->info().mass, 0.0);
  expect_invariants("after one interior split");
}

TEST_F(SplitEdgeTest, TheTwoFacesOfAnInteriorEdgeGoUpOneRefinementLevel) {
  const std::vector<float> before = face_refinement_level(lcc);
  for (float level : before) EXPECT_EQ(level, 0.0f);
  split_edge(lcc, dart_between(8, 9), springs);
  const std::vector<float> after = face_refinement_level(lcc);
  ASSERT_EQ(after.size(), before.size() + 2);
  // the edge's two triangles became four halves, each at level 1; the others stay at 0
  EXPECT_EQ(
      std::count_if(after.begin(), after.end(), [](float l) { return std::abs(l - 1.0f) < 1e-6f; }),
      4);
  EXPECT_EQ(std::count(after.begin(), after.end(), 0.0f), static_cast<long>(before.size()) - 2);
}

TEST_F(SplitEdgeTest, BoundarySplitAddsOneFace) {
  const std::size_t faces = lcc.attributes<2>().size();
  split_edge(lcc, dart_between(0, 1), springs);
  EXPECT_EQ(lcc.attributes<2>().size(), faces + 1);
  expect_invariants("after one boundary split");
}

TEST_F(SplitEdgeTest, EverySplitOfARandomBatchKeepsTheInvariantsAndThePins) {
  std::mt19937 random(7);
  for (int k = 0; k < 60; ++k) {
    std::vector<Dart_handle> darts;
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) darts.push_back(d);
    split_edge(lcc, darts[random() % darts.size()], springs);
    expect_invariants("after split " + std::to_string(k));
    if (HasFailure()) return;
  }
  int still_pinned = 0;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    still_pinned += v->info().pinned && v->info().source_index >= 0;
  }
  EXPECT_EQ(still_pinned, pinned);
}

TEST_F(SplitEdgeTest, TheMidpointOfAClampedEdgeIsPinnedAndOfAnyOtherIsFree) {
  // the top row (pinned) has source ids 35 to 41, right to left along the border; 28 is below 35
  const Dart_handle on_clamp = split_edge(lcc, dart_between(36, 35), springs);
  EXPECT_TRUE(lcc.vertex_attribute(on_clamp)->info().pinned);
  const Dart_handle off_clamp = split_edge(lcc, dart_between(35, 28), springs);
  EXPECT_FALSE(lcc.vertex_attribute(off_clamp)->info().pinned);
  expect_invariants("after splitting a clamped edge");
}

TEST_F(SplitEdgeTest, ClothAtRestInItsRestShapeStaysAtRest) {
  std::mt19937 random(3);
  for (int k = 0; k < 30; ++k) {
    std::vector<Dart_handle> darts;
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) darts.push_back(d);
    split_edge(lcc, darts[random() % darts.size()], springs);
  }
  const CompiledCloth cloth = compile(lcc);
  Environment no_load;
  no_load.gravity.setZero();
  no_load.wind.air_density = 0.0;
  ForceWorkspace workspace;
  Eigen::VectorXd force;
  accumulate_forces(cloth.model, no_load, 0.0, cloth.state.x, cloth.state.v, workspace, force);
  EXPECT_LT(force.cwiseAbs().maxCoeff(), 1e-12 * springs.structural.stiffness);  // N
}

TEST_F(SplitEdgeTest, MomentumAndCentreOfMassAreUnchanged) {
  // a deformed, moving cloth
  std::mt19937 random(11);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    v->point() = v->point() + Vector3(noise(random), noise(random), noise(random));
    v->info().velocity = Vector3(noise(random), noise(random), noise(random)) * 20.0;
  }
  auto moments = [&] {
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero(), first_moment = Eigen::Vector3d::Zero();
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      const double m = v->info().mass;
      momentum += m * to_eigen(v->info().velocity);
      first_moment += m * to_eigen(v->point());
    }
    return std::pair{momentum, first_moment};
  };
  const auto [momentum_before, moment_before] = moments();
  for (auto [a, b] : {std::pair{8, 9}, {0, 1}, {15, 22}, {9, 16}}) {
    split_edge(lcc, dart_between(a, b), springs);
  }
  const auto [momentum_after, moment_after] = moments();
  EXPECT_LT((momentum_after - momentum_before).norm(), 1e-14);  // kg m/s
  EXPECT_LT((moment_after - moment_before).norm(), 1e-14);      // kg m: centre of mass x mass
}

TEST(SplitEdge, RefusesQuads) {
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(test::grid(2, 2, GridCells::quads)), 0.2, test::all_springs(),
                      lcc);
  EXPECT_THROW(split_edge(lcc, lcc.darts().begin(), test::all_springs()), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
