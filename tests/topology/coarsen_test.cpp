#include "topology/coarsen.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "cloth_test_support.hpp"
#include "topology/mass_lumping.hpp"
#include "topology/refine.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;

class CoarsenTest : public ::testing::Test {
 protected:
  void SetUp() override {
    options = test::grid(8, 6, GridCells::triangles);
    test::build_grid_pinned_at_top(options, density_kg_per_m2, springs, lcc);
    original_masses = masses_by_source();
  }
  std::map<int, double> masses_by_source() {
    std::map<int, double> out;
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      out[v->info().source_index] = v->info().mass;
    }
    return out;
  }
  /// Stretches the cloth right of x = 0.6 m by 30 % and refines it three times by strain.
  void refine_stretched_part() {
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      const Point3& p = v->point();
      if (p.x() > 0.6) v->point() = Point3(0.6 + 1.3 * (p.x() - 0.6), p.y(), p.z());
    }
    refinement.strain_threshold = 0.05;
    refinement.min_edge_length_m = 0.005;
    for (int pass = 0; pass < 3; ++pass) refine(lcc, refinement, springs);
    ASSERT_GT(lcc.vertex_attributes().size(), original_masses.size());
  }
  int coarsen_fully(const RefinementOptions& criteria, double hysteresis) {
    int merges = 0;
    for (int pass = 0; pass < 100; ++pass) {
      const int merged = coarsen(lcc, criteria, hysteresis, springs).merges;
      const auto problems = validity_problems(lcc);
      EXPECT_TRUE(problems.empty()) << "pass " << pass << ": " << problems.front();
      if (merged == 0) break;
      merges += merged;
    }
    return merges;
  }
  double expected_mass_kg() const { return density_kg_per_m2 * options.width * options.height; }

  GridOptions options;
  SpringSettings springs = test::all_springs();
  RefinementOptions refinement;
  ClothComplex lcc;
  std::map<int, double> original_masses;
};

TEST_F(CoarsenTest, RefineThenCoarsenWithCriteriaOffRestoresParticlesAndMasses) {
  refine_stretched_part();
  const int created = static_cast<int>(lcc.vertex_attributes().size() - original_masses.size());
  EXPECT_EQ(coarsen_fully(RefinementOptions{}, 0.5), created);
  ASSERT_EQ(lcc.vertex_attributes().size(), original_masses.size());
  const std::map<int, double> masses = masses_by_source();
  for (const auto& [source, mass_kg] : original_masses) {
    ASSERT_TRUE(masses.count(source)) << "particle " << source << " was removed";
    EXPECT_NEAR(masses.at(source), mass_kg, 1e-12 * mass_kg) << "particle " << source;
  }
  EXPECT_NEAR(complex_total_mass(lcc), expected_mass_kg(), 1e-12 * expected_mass_kg());
  int pinned = 0;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    pinned += v->info().pinned;
  }
  EXPECT_EQ(pinned, options.cells_u + 1);
}

TEST_F(CoarsenTest, StillStretchedCellsStayRefined) {
  refine_stretched_part();
  const std::size_t refined = lcc.vertex_attributes().size();
  coarsen_fully(refinement, 0.5);
  EXPECT_EQ(lcc.vertex_attributes().size(), refined);
}

// adapt()'s pass: coarsening on the field refinement computed. The faces refinement split hold
// their parent's sizing, so none of its particles is undone at once (the last of the three
// passes split 144 edges); with a field that wants nothing (all sizing 0) the same call undoes
// them.
TEST_F(CoarsenTest, RightAfterRefinementTheFieldItComputedUndoesNoneOfItsSplits) {
  refine_stretched_part();
  const std::size_t refined = lcc.vertex_attributes().size();
  EXPECT_EQ(coarsen_on_current_sizing(lcc, refinement, 0.5, springs).merges, 0);
  EXPECT_EQ(lcc.vertex_attributes().size(), refined);
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    f->info().sizing_per_m2 = 0.0;
  }
  EXPECT_GT(coarsen_on_current_sizing(lcc, refinement, 0.5, springs).merges, 0);
  test::expect_valid_with_mass(lcc, expected_mass_kg());
}

TEST_F(CoarsenTest, CoarseningConservesMassAndMomentum) {
  refine_stretched_part();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> speed(-1.0, 1.0);
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (!v->info().pinned)
      v->info().velocity = Vector3(speed(random), speed(random), speed(random));
  }
  const Eigen::Vector3d momentum_before = test::complex_momentum(lcc);
  EXPECT_GT(coarsen_fully(RefinementOptions{}, 0.5), 0);
  EXPECT_LT((test::complex_momentum(lcc) - momentum_before).norm(), 1e-14);  // kg m/s
  EXPECT_NEAR(complex_total_mass(lcc), expected_mass_kg(), 1e-12 * expected_mass_kg());
}

TEST_F(CoarsenTest, InputParticlesAreNeverRemoved) {
  EXPECT_EQ(coarsen(lcc, RefinementOptions{}, 0.5, springs).merges, 0);
  EXPECT_EQ(lcc.vertex_attributes().size(), original_masses.size());
}

}  // namespace
}  // namespace tissu
