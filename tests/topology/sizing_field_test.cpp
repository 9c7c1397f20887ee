// The sizing field that drives refinement (topology/sizing_field.hpp): what refines, what does not,
// and how far the refined band spreads; and the bending springs' scaling across levels.
#include "topology/sizing_field.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "cloth_test_support.hpp"
#include "topology/coarsen.hpp"
#include "topology/refine.hpp"
#include "topology/rest_geometry.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;
constexpr double pi = 3.14159265358979323846;

/// 1.5 m x 0.9 m in the x-z plane from (0.2, -0.1, 0.3), 12 x 8 cells of 12.5 cm x 11.25 cm.
GridOptions sheet() {
  return test::grid(12, 8, GridCells::triangles);
}

/// The sheet rolled about the z axis into a cylinder of radius `radius_m`: its rest shape is
/// curved everywhere.
IndexedMesh rolled_sheet(double radius_m) {
  IndexedMesh mesh = make_grid_mesh(sheet());
  for (Eigen::Vector3d& x : mesh.vertices) {
    const double angle = (x.x() - 0.2) / radius_m;
    x = Eigen::Vector3d(0.2 + radius_m * std::sin(angle), -0.1 + radius_m * (1.0 - std::cos(angle)),
                        x.z());
  }
  return mesh;
}

/// Refines `lcc` with `options` until a pass splits nothing (at most 20 passes); returns the
/// number of splits.
int refine_fully(ClothComplex& lcc, const RefinementOptions& options, const SpringSettings& springs,
                 const SizingInputs& inputs = {}) {
  int splits = 0;
  for (int pass = 0; pass < 20; ++pass) {
    const int made = refine(lcc, options, springs, inputs).splits;
    if (made == 0) break;
    splits += made;
  }
  return splits;
}

RefinementOptions curvature_only(double angle_rad) {
  RefinementOptions o;
  o.curvature_threshold_rad = angle_rad;
  o.min_edge_length_m = 0.01;
  return o;
}

class SizingFieldTest : public ::testing::Test {
 protected:
  SpringSettings springs = test::all_springs();
  ClothComplex lcc;
  double expected_mass_kg() const { return density_kg_per_m2 * 1.5 * 0.9; }
};

TEST_F(SizingFieldTest, AFlatSheetAtRestRefinesNothing) {
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  RefinementOptions options = curvature_only(0.1);
  options.strain_threshold = 0.01;
  options.lookahead_s = 0.1;
  EXPECT_EQ(refine_fully(lcc, options, springs), 0);
}

TEST_F(SizingFieldTest, ACurvedRestShapeAtRestRefinesNothingAndFlatteningItRefines) {
  build_cloth_complex(rolled_sheet(0.3), density_kg_per_m2, springs, lcc);
  const double mass_kg = complex_total_mass(lcc);  // of the chords' area, a little under 1.5 x 0.9
  const RefinementOptions options = curvature_only(0.1);
  // the sheet turns by 0.42 rad per 12.5 cm cell, four times the threshold: an absolute measure
  // of curvature would refine it all
  EXPECT_EQ(refine_fully(lcc, options, springs), 0);
  // pressed flat, it is now bent relative to its rest shape everywhere
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    v->point() = Point3(v->point().x(), -0.1, v->point().z());
  }
  EXPECT_GT(refine(lcc, options, springs).splits, 0);
  test::expect_valid_with_mass(lcc, mass_kg, "after refining the flattened sheet");
}

TEST_F(SizingFieldTest, AFoldRefinesOnlyABandAroundIt) {
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  // a 90 degree crease along the grid line x = 0.95 m
  const double crease_x_m = 0.95;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    if (p.x() > crease_x_m) v->point() = Point3(crease_x_m, p.y() + (p.x() - crease_x_m), p.z());
  }
  const std::size_t before = lcc.vertex_attributes().size();
  ASSERT_GT(refine_fully(lcc, curvature_only(0.5), springs), 0);
  EXPECT_GT(lcc.vertex_attributes().size(), before);
  // every new particle within two cells of the crease; the faces cut from input faces (smaller
  // than them) cover at most 4 of the 12 columns of cells
  const double cell_m = 1.5 / 12;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (v->info().source_index >= 0) continue;
    EXPECT_LT(std::abs(v->info().rest_position.x() - crease_x_m), 2.0 * cell_m)
        << "a particle at rest x " << v->info().rest_position.x();
  }
  double refined_m2 = 0.0;
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    if (f->info().rest_area < 0.99 * f->info().input_area) refined_m2 += f->info().rest_area;
  }
  EXPECT_LE(refined_m2, 4.0 / 12.0 * 1.5 * 0.9);
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "after refining the fold");
}

TEST_F(SizingFieldTest, TheVelocityTermRefinesAFoldBeforeItForms) {
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  // flat, but the right part turns about the line x = 0.95 m at 5 rad/s: folded by 0.5 rad in 0.1 s
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const double arm_m = v->point().x() - 0.95;
    if (arm_m > 0.0) v->info().velocity = Vector3(0.0, 5.0 * arm_m, 0.0);
  }
  RefinementOptions options = curvature_only(0.5);
  EXPECT_EQ(refine(lcc, options, springs).splits, 0) << "without looking ahead";
  options.lookahead_s = 0.1;
  EXPECT_GT(refine(lcc, options, springs).splits, 0) << "looking 0.1 s ahead";
  test::expect_valid_with_mass(lcc, expected_mass_kg());
}

/// How many faces of `lcc` the sizing field last held by `term`.
int faces_held_by(const ClothComplex& lcc, SizingTerm term) {
  int count = 0;
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    count += f->info().sizing_term == term ? 1 : 0;
  }
  return count;
}

TEST_F(SizingFieldTest, EachFaceNamesTheTermThatHoldsIt) {
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  const int faces = static_cast<int>(lcc.attributes<2>().size());
  RefinementOptions options = curvature_only(0.5);
  options.strain_threshold = 0.1;
  options.lookahead_s = 0.1;
  compute_sizing(lcc, options, {});
  EXPECT_EQ(faces_held_by(lcc, SizingTerm::none), faces) << "flat and at rest";

  // the right part turns about the grid line x = 0.95 m at 5 rad/s: only the velocity term sees
  // the fold that will form there
  const double hinge_x_m = 0.95;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const double arm_m = v->point().x() - hinge_x_m;
    if (arm_m > 0.0) v->info().velocity = Vector3(0.0, 5.0 * arm_m, 0.0);
  }
  compute_sizing(lcc, options, {});
  const int ahead = faces_held_by(lcc, SizingTerm::velocity);
  EXPECT_GT(ahead, 0);
  EXPECT_EQ(faces_held_by(lcc, SizingTerm::none), faces - ahead);

  // folded there by 90 degrees now: the curvature term holds the faces along the crease
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    if (p.x() > hinge_x_m) v->point() = Point3(hinge_x_m, p.y() + (p.x() - hinge_x_m), p.z());
    v->info().velocity = Vector3(0.0, 0.0, 0.0);
  }
  compute_sizing(lcc, options, {});
  const int creased = faces_held_by(lcc, SizingTerm::curvature);
  EXPECT_GT(creased, 0);
  EXPECT_LE(creased, faces / 3);  // a band along the crease
  EXPECT_EQ(faces_held_by(lcc, SizingTerm::velocity), 0);

  // flat again, stretched by 25 % along x: every face has a strained edge
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    v->point() = Point3(0.2 + 1.25 * (p.x() - 0.2), p.y(), p.z());
  }
  compute_sizing(lcc, options, {});
  EXPECT_EQ(faces_held_by(lcc, SizingTerm::strain), faces);

  // at rest with a maximum edge length under the cells' size: that floor holds them all
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  options.max_edge_length_m = 0.1;
  compute_sizing(lcc, options, {});
  EXPECT_EQ(faces_held_by(lcc, SizingTerm::max_edge_length), faces);
}

TEST_F(SizingFieldTest,
       TheObstacleTermRefinesWhereTheClothComesDownOnAnObstacleNotWhereItLiesFlat) {
  // the sheet lies horizontal (the x-y plane), 2 mm above a floor: flat on it, nothing to refine
  GridOptions flat = sheet();
  flat.v_axis = Eigen::Vector3d::UnitY();
  flat.origin = Eigen::Vector3d(0.0, 0.0, 0.002);
  build_cloth_complex(make_grid_mesh(flat), density_kg_per_m2, springs, lcc);
  std::vector<Obstacle> floor(1);
  floor[0].thickness_m = 0.002;
  const SizingInputs inputs{&floor, 0.0};
  RefinementOptions options;
  options.min_edge_length_m = 0.02;
  EXPECT_EQ(refine_fully(lcc, options, springs, inputs), 0);
  // tilted by 0.2 rad about its edge x = 0, which stays on the floor: the cells near that edge
  // come down on it
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    v->point() = Point3(p.x() * std::cos(0.2), p.y(), 0.002 + p.x() * std::sin(0.2));
  }
  ASSERT_GT(refine_fully(lcc, options, springs, inputs), 0);
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (v->info().source_index < 0) {
      EXPECT_LT(v->info().rest_position.x(), 0.5);
    }
  }
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "after refining near the floor");
}

/// The centre of sheet() (m).
Eigen::Vector3d sheet_middle() {
  const GridOptions o = sheet();
  return o.origin + 0.5 * (o.width * o.u_axis + o.height * o.v_axis);
}

/// The centre of a ball of radius `radius_m` on which sheet() lies at its centre, `thickness_m`
/// above it, on the side its normal u x v points to.
Eigen::Vector3d ball_under_sheet(double radius_m, double thickness_m) {
  const GridOptions o = sheet();
  return sheet_middle() + (radius_m + thickness_m) * o.u_axis.cross(o.v_axis);
}

/// The sheet laid on the ball of ball_under_sheet(), every vertex `thickness_m` above it, at the
/// geodesic distance from the sheet's centre that it has at rest (an azimuthal equidistant map:
/// lengths from the centre kept).
void lay_on_sphere(ClothComplex& lcc, double radius_m, double thickness_m) {
  const Eigen::Vector3d middle = sheet_middle();
  const Eigen::Vector3d centre = ball_under_sheet(radius_m, thickness_m);
  const Eigen::Vector3d up = (middle - centre).normalized();
  const double lying_m = radius_m + thickness_m;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Eigen::Vector3d offset = to_eigen(v->info().rest_position) - middle;
    const double distance_m = offset.norm();
    const double angle = distance_m / lying_m;
    const Eigen::Vector3d along =
        distance_m > 0.0 ? Eigen::Vector3d(offset / distance_m) : sheet().u_axis;
    v->point() = to_point(centre + lying_m * (std::cos(angle) * up + std::sin(angle) * along));
  }
}

TEST_F(SizingFieldTest,
       OnACurvedObstacleTheObstacleTermSplitsFacesWhoseChordsSagMoreThanTheThickness) {
  // A face of longest edge L lying on a ball of radius R sags by L^2 / (8 R) below its corners:
  // on a ball of 0.6 m with a 2 mm thickness, the 12.5 cm cells' 16.8 cm diagonals sag by 5.9 mm,
  // the 6.25 cm cells' 8.4 cm diagonals by 1.5 mm. ARCSim's metric alone would split both
  // (L > sqrt(2 R t) = 4.9 cm).
  const double radius_m = 0.6, thickness_m = 0.002;
  std::vector<Obstacle> ball(1);
  ball[0].shape = ObstacleShape::sphere;
  ball[0].position = ball_under_sheet(radius_m, thickness_m);
  ball[0].radius_m = radius_m;
  ball[0].thickness_m = thickness_m;
  RefinementOptions options;
  options.min_edge_length_m = 0.005;
  const SizingInputs inputs{&ball, 0.0};
  for (const int cells : {24, 48}) {
    ClothComplex fine;
    build_cloth_complex(make_grid_mesh(test::grid(cells, cells * 2 / 3, GridCells::triangles)),
                        density_kg_per_m2, springs, fine);
    lay_on_sphere(fine, radius_m, thickness_m);
    EXPECT_EQ(refine(fine, options, springs, inputs).splits, 0) << cells << " cells";
  }
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  lay_on_sphere(lcc, radius_m, thickness_m);
  EXPECT_GT(refine(lcc, options, springs, inputs).splits, 0) << "12 cells";
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "after refining on the ball");
}

TEST_F(SizingFieldTest, CoarseningWaitsForTheGivenNumberOfCalmPasses) {
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  RefinementOptions fine;
  fine.max_edge_length_m = 0.1;  // every 12.5 cm leg is split
  ASSERT_GT(refine(lcc, fine, springs).splits, 0);
  RefinementOptions calm;  // no term: everything is calm
  calm.coarsen_after_passes = 3;
  EXPECT_EQ(coarsen(lcc, calm, 0.5, springs).merges, 0);
  EXPECT_EQ(coarsen(lcc, calm, 0.5, springs).merges, 0);
  EXPECT_GT(coarsen(lcc, calm, 0.5, springs).merges, 0) << "the third calm pass";
  test::expect_valid_with_mass(lcc, expected_mass_kg());
}

TEST_F(SizingFieldTest, TwoLevelsOfBisectionMakeTheBendingSpringsThoseOfTheTwiceFinerGrid) {
  // two bisections of every right isosceles cell give the grid of half the cell size; the same
  // cloth on that grid has bending springs (A_input / A)^2 = 16 times as stiff
  // (spring_assignment.cpp)
  build_cloth_complex(make_grid_mesh(sheet()), density_kg_per_m2, springs, lcc);
  RefinementOptions fine;
  // below the legs (12.5 cm, 11.25 cm), above the half cells' diagonals (8.4 cm)
  fine.max_edge_length_m = 0.1;
  refine_fully(lcc, fine, springs);
  ASSERT_EQ(lcc.vertex_attributes().size(), 25u * 17u);  // the 24 x 16 grid's particles
  int bending = 0;
  for (auto e = lcc.attributes<1>().begin(); e != lcc.attributes<1>().end(); ++e) {
    const StoredSpring& spring = e->info().bending;
    if (spring.slot != SpringSlot::present) continue;
    EXPECT_NEAR(spring.stiffness, 16.0 * springs.bending.stiffness, 1e-9);
    ++bending;
  }
  EXPECT_GT(bending, 0);
  // and undone, they are the scenario's again
  coarsen(lcc, RefinementOptions{}, 0.5, springs);
  coarsen(lcc, RefinementOptions{}, 0.5, springs);
  ASSERT_EQ(lcc.vertex_attributes().size(), 13u * 9u);
  for (auto e = lcc.attributes<1>().begin(); e != lcc.attributes<1>().end(); ++e) {
    const StoredSpring& spring = e->info().bending;
    if (spring.slot == SpringSlot::present) {
      EXPECT_NEAR(spring.stiffness, springs.bending.stiffness, 1e-12);
    }
  }
}

}  // namespace
}  // namespace tissu
