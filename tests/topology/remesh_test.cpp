// Anisotropic remeshing (topology/remesh.hpp): what refines, how the cells lie along a fold, and
// that unfolding gives the particles back; the invariants after every pass.
#include "topology/remesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cloth_test_support.hpp"
#include "topology/local_update.hpp"
#include "topology/refine.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/sizing_metric.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;
constexpr double crease_x_m = 0.95;  // a grid line of the sheet

/// 1.5 m x 0.9 m in the x-z plane from (0.2, -0.1, 0.3), 12 x 8 cells of 12.5 cm x 11.25 cm.
GridOptions sheet() {
  return test::grid(12, 8, GridCells::triangles);
}

RefinementOptions anisotropic_curvature(double angle_rad) {
  RefinementOptions o;
  o.anisotropic = true;
  o.curvature_threshold_rad = angle_rad;
  o.min_edge_length_m = 0.01;
  return o;
}

/// Folds the part of the sheet right of x = crease_x_m by 90 degrees about that line.
void fold(ClothComplex& lcc) {
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& r = v->info().rest_position;
    v->point() = r.x() > crease_x_m ? Point3(crease_x_m, r.y() + (r.x() - crease_x_m), r.z()) : r;
  }
}

void unfold(ClothComplex& lcc) {
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    v->point() = v->info().rest_position;
  }
}

class RemeshTest : public ::testing::Test {
 protected:
  void SetUp() override {
    build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  }
  double expected_mass_kg() const { return density_kg_per_m2 * 1.5 * 0.9; }
  /// Remeshes until a pass changes nothing (at most 20 passes), checking the invariants after
  /// each; returns the sum of the passes' reports.
  RemeshReport remesh_fully(const RefinementOptions& options, double hysteresis) {
    RemeshReport total;
    for (int pass = 0; pass < 20; ++pass) {
      const RemeshReport r = remesh(lcc, options, hysteresis, springs);
      test::expect_valid_with_mass(lcc, expected_mass_kg(), "pass " + std::to_string(pass));
      total.splits += r.splits;
      total.flips += r.flips;
      total.collapses += r.collapses;
      if (r.splits + r.flips + r.collapses == 0) return total;
    }
    ADD_FAILURE() << "remeshing still changes the cloth after 20 passes";
    return total;
  }
  SpringSettings springs = test::all_springs();
  ClothComplex lcc;
};

TEST_F(RemeshTest, AFlatSheetAtRestRemeshesNothing) {
  RefinementOptions options = anisotropic_curvature(0.1);
  options.strain_threshold = 0.01;
  options.lookahead_s = 0.1;
  const RemeshReport r = remesh_fully(options, 0.5);
  EXPECT_EQ(r.splits, 0);
  EXPECT_EQ(r.flips, 0);
  EXPECT_EQ(r.collapses, 0);
}

TEST_F(RemeshTest, ACurvedRestShapeAtRestRemeshesNothing) {
  // the sheet rolled about the z axis into a cylinder of radius 0.3 m: it turns by 0.42 rad per
  // cell, four times the threshold, so an absolute measure of curvature would refine it all
  IndexedMesh rolled = make_grid_mesh(sheet());
  for (Eigen::Vector3d& x : rolled.vertices) {
    const double angle = (x.x() - 0.2) / 0.3;
    x = Eigen::Vector3d(0.2 + 0.3 * std::sin(angle), -0.1 + 0.3 * (1.0 - std::cos(angle)), x.z());
  }
  build_cloth_complex(rolled, density_kg_per_m2, springs, lcc);
  const RemeshReport r = remesh(lcc, anisotropic_curvature(0.1), 0.5, springs);
  EXPECT_EQ(r.splits + r.flips + r.collapses, 0);
}

TEST_F(RemeshTest, AFoldIsRefinedInABandOfCellsLongAlongIt) {
  const std::size_t input = lcc.vertex_attributes().size();
  fold(lcc);
  const RefinementOptions options = anisotropic_curvature(0.5);
  const RemeshReport r = remesh_fully(options, 0.0);
  ASSERT_GT(r.splits, 0);
  const std::size_t anisotropic = lcc.vertex_attributes().size();

  // every new particle within two cells of the crease
  const double cell_m = 1.5 / 12;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (v->info().source_index >= 0) continue;
    EXPECT_LT(std::abs(v->info().rest_position.x() - crease_x_m), 2.0 * cell_m)
        << "a particle at rest x " << v->info().rest_position.x();
  }
  // the pass converged: no edge is longer than the metric wants unless splitting it would go
  // under the shortest edge allowed
  compute_sizing_metric(lcc, options, {});
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    if (edge_rest_length_m(lcc, d) >= 2.0 * options.min_edge_length_m) {
      EXPECT_LE(edge_metric_length2(lcc, d), 1.0);
    }
  }
  // the faces along the crease are long along it (z) and short across it (x)
  int long_along = 0;
  for (auto f = lcc.one_dart_per_cell<2>().begin(); f != lcc.one_dart_per_cell<2>().end(); ++f) {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9), high = -low;
    for (auto d = lcc.darts_of_orbit<1>(f).begin(); d != lcc.darts_of_orbit<1>(f).end(); ++d) {
      const Eigen::Vector3d r = to_eigen(lcc.vertex_attribute(d)->info().rest_position);
      low = low.cwiseMin(r);
      high = high.cwiseMax(r);
    }
    if (low.x() < crease_x_m + 1e-9 && high.x() > crease_x_m - 1e-9 &&
        high.z() - low.z() > 2.0 * (high.x() - low.x())) {
      ++long_along;
    }
  }
  EXPECT_GT(long_along, 0);

  // bisection at the same threshold needs more particles for the same fold
  ClothComplex bisected;
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, bisected);
  fold(bisected);
  RefinementOptions isotropic = options;
  isotropic.anisotropic = false;
  for (int pass = 0; pass < 20 && refine(bisected, isotropic, springs).splits > 0; ++pass) {
  }
  // (on this sheet, 142 new particles against bisection's 414)
  EXPECT_LT(anisotropic - input, bisected.vertex_attributes().size() - input);
}

TEST_F(RemeshTest, UnfoldingCollapsesTheFoldsParticlesAway) {
  const std::size_t input = lcc.vertex_attributes().size();
  fold(lcc);
  const RefinementOptions options = anisotropic_curvature(0.5);
  remesh_fully(options, 0.5);
  const std::size_t folded = lcc.vertex_attributes().size();
  ASSERT_GT(folded, input);
  unfold(lcc);
  const RemeshReport r = remesh_fully(options, 0.5);
  EXPECT_GT(r.collapses, 0);
  EXPECT_EQ(lcc.vertex_attributes().size(), input);
}

TEST(BendingHingeShape, ARefinedThinHingeIsStifferByItsShapeCubedAndAnInputOneIsNot) {
  // a 4 m x 1 m rectangle cut along its diagonal: the hinge's shape rho = l^2 / A = 17 / 4
  IndexedMesh rectangle;
  rectangle.vertices = {{0, 0, 0}, {4, 0, 0}, {4, 1, 0}, {0, 1, 0}};
  rectangle.faces = {{0, 1, 2}, {0, 2, 3}};
  SpringSettings springs = test::all_springs();
  springs.bending_follows_hinge_shape = true;
  ClothComplex lcc;
  build_cloth_complex(rectangle, density_kg_per_m2, springs, lcc);
  const auto bending_n_per_m = [&] {
    for (auto e = lcc.attributes<1>().begin(); e != lcc.attributes<1>().end(); ++e) {
      if (e->info().bending.slot == SpringSlot::present) return e->info().bending.stiffness;
    }
    return 0.0;
  };
  EXPECT_DOUBLE_EQ(bending_n_per_m(), springs.bending.stiffness);  // input faces: as given
  // as if both faces had been cut from input faces twice their size
  std::vector<Dart_handle> faces;
  for (auto f = lcc.one_dart_per_cell<2>().begin(); f != lcc.one_dart_per_cell<2>().end(); ++f) {
    lcc.info<2>(f).input_area = 2.0 * lcc.info<2>(f).rest_area;
    faces.push_back(f);
  }
  update_around_faces(lcc, faces, springs);
  const double rho = 17.0 / 4.0;
  EXPECT_NEAR(bending_n_per_m(), springs.bending.stiffness * 4.0 * rho * rho * rho, 1e-9);
  springs.bending_follows_hinge_shape = false;
  update_around_faces(lcc, faces, springs);
  EXPECT_NEAR(bending_n_per_m(), springs.bending.stiffness * 4.0, 1e-12);
}

}  // namespace
}  // namespace tissu
