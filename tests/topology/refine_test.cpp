#include "topology/refine.hpp"

#include <gtest/gtest.h>

#include "cloth_test_support.hpp"
#include "topology/coarsen.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;

class RefineTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // 1.5 m x 0.9 m in the x-z plane from (0.2, -0.1, 0.3), 12 x 8 cells
    options = test::grid(12, 8, GridCells::triangles);
    build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, springs, lcc);
  }
  void expect_valid_and_mass_conserved() {
    test::expect_valid_with_mass(lcc, density_kg_per_m2 * options.width * options.height);
  }
  /// Stretches the cloth by `factor` along x for rest x beyond `from_x_m`.
  void stretch_right_part(double from_x_m, double factor) {
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      const Point3& p = v->point();
      if (p.x() > from_x_m)
        v->point() = Point3(from_x_m + factor * (p.x() - from_x_m), p.y(), p.z());
    }
  }
  GridOptions options;
  SpringSettings springs = test::all_springs();
  ClothComplex lcc;
};

TEST_F(RefineTest, FlatSheetDoesNotRefineByCurvature) {
  RefinementOptions refinement;
  refinement.curvature_threshold_rad = 0.05;
  const RefinementReport report = refine(lcc, refinement, springs);
  EXPECT_EQ(report.candidate_faces, 0);
  EXPECT_EQ(report.splits, 0);
}

TEST_F(RefineTest, StrainRefinesOnlyWhereTheSheetIsStretched) {
  const double from_x_m = 0.2 + 0.75;  // the right half
  stretch_right_part(from_x_m, 1.2);
  RefinementOptions refinement;
  refinement.strain_threshold = 0.1;
  const std::size_t before = lcc.vertex_attributes().size();
  const RefinementReport report = refine(lcc, refinement, springs);
  EXPECT_GT(report.splits, 0);
  EXPECT_GT(lcc.vertex_attributes().size(), before);
  // new particles lie on edges of triangles touching the stretched half: at most one cell left
  const double cell_m = options.width / options.cells_u;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (v->info().source_index < 0) {
      EXPECT_GT(v->info().rest_position.x(), from_x_m - cell_m);
    }
  }
  expect_valid_and_mass_conserved();
}

TEST_F(RefineTest, CurvatureRefinesAFold) {
  // fold the sheet along x = 0.95 m by 90 degrees
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    if (p.x() > 0.95) v->point() = Point3(0.95, p.y() + (p.x() - 0.95), p.z());
  }
  RefinementOptions refinement;
  refinement.curvature_threshold_rad = 0.5;
  const RefinementReport report = refine(lcc, refinement, springs);
  // the two triangles on either side of each edge of the grid line x = 0.95 m: cells stay flat
  EXPECT_EQ(report.candidate_faces, 2 * options.cells_v);
  EXPECT_GT(report.splits, 0);
  expect_valid_and_mass_conserved();
}

TEST_F(RefineTest, RepeatedPassesStopAtTheMinimumEdgeLengthAndTheParticleCap) {
  stretch_right_part(0.2, 1.5);
  RefinementOptions refinement;
  refinement.strain_threshold = 0.01;
  refinement.min_edge_length_m = 0.02;
  int passes = 0;
  while (refine(lcc, refinement, springs).splits > 0 && passes < 50) ++passes;
  EXPECT_LT(passes, 50);
  expect_valid_and_mass_conserved();
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    EXPECT_GE(lcc.info<1>(d).structural.rest_length, refinement.min_edge_length_m);
  }

  ClothComplex capped;
  build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, springs, capped);
  std::swap(lcc, capped);
  stretch_right_part(0.2, 1.5);
  refinement.max_particles = 150;  // the grid has 117
  while (refine(lcc, refinement, springs).splits > 0) {
  }
  EXPECT_EQ(lcc.vertex_attributes().size(), 150u);
}

/// The smallest angle of the triangle of `d` in rest space (radians).
double smallest_rest_angle(const ClothComplex& lcc, Dart_const_handle d) {
  std::vector<Point3> corners;
  for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
    corners.push_back(lcc.vertex_attribute(e)->info().rest_position);
  }
  double smallest = M_PI;
  for (int i = 0; i < 3; ++i) {
    const Vector3 u = corners[(i + 1) % 3] - corners[i];
    const Vector3 w = corners[(i + 2) % 3] - corners[i];
    smallest =
        std::min(smallest, std::acos(u * w / std::sqrt(u.squared_length() * w.squared_length())));
  }
  return smallest;
}

TEST_F(RefineTest, LongestEdgePropagationKeepsRightIsoscelesTrianglesSimilar) {
  // square cells of 0.1 m: every initial triangle is right isosceles (smallest angle 45 degrees);
  // bisecting a leg instead of a hypotenuse would make a 26.6-degree corner
  options = test::grid(15, 9, GridCells::triangles);
  lcc.clear();
  build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, springs, lcc);
  stretch_right_part(1.0, 1.2);
  RefinementOptions refinement;
  refinement.strain_threshold = 0.05;
  refinement.min_edge_length_m = 0.01;
  int splits = 0;
  for (int pass = 0; pass < 4; ++pass) splits += refine(lcc, refinement, springs).splits;
  EXPECT_GT(splits, 100);
  expect_valid_and_mass_conserved();
  for (auto f = lcc.one_dart_per_cell<2>().begin(); f != lcc.one_dart_per_cell<2>().end(); ++f) {
    EXPECT_NEAR(smallest_rest_angle(lcc, f), M_PI / 4.0, 1e-9);
  }
}

TEST_F(RefineTest, MaxEdgeLengthRefinesAFlatSheetAndCoarseningKeepsIt) {
  // 12 x 8 cells of 0.125 m x 0.1125 m: every edge must end at most 0.1 m long
  RefinementOptions refinement;
  refinement.max_edge_length_m = 0.1;
  refinement.min_edge_length_m = 0.01;
  while (refine(lcc, refinement, springs).splits > 0) {
  }
  expect_valid_and_mass_conserved();
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    EXPECT_LE(lcc.info<1>(d).structural.rest_length, 0.1);
  }
  const std::size_t refined = lcc.vertex_attributes().size();
  EXPECT_GT(refined, 117u);
  EXPECT_EQ(coarsen(lcc, refinement, 0.5, springs).merges, 0);  // flat and calm, but not longer
  EXPECT_EQ(lcc.vertex_attributes().size(), refined);
}

}  // namespace
}  // namespace tissu
