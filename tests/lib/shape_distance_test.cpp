// Comparing two runs of one cloth at different resolutions through their material points.

#include "lib/shape_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "topology/grid_mesh.hpp"

namespace tissu {
namespace {

/// A flat 1 m x 0.5 m sheet on `cells` x `cells` cells, its current shape given by `shape`.
template <class Shape>
MaterialSurface sheet(int cells, GridCells kind, Shape shape) {
  GridOptions o;
  o.width = 1.0;
  o.height = 0.5;
  o.cells_u = cells;
  o.cells_v = cells;
  o.cells = kind;
  MaterialSurface s{make_grid_mesh(o), {}};
  s.rest_m = s.current.vertices;
  for (Eigen::Vector3d& x : s.current.vertices) x = shape(x);
  return s;
}

Eigen::Vector3d sheared_and_lifted(const Eigen::Vector3d& X) {
  // an affine map: reproduced exactly by any mesh's piecewise-linear interpolation
  return Eigen::Vector3d(1.1 * X.x() + 0.3 * X.z(), 0.2 * X.x() + 0.05, 0.9 * X.z());
}

Eigen::Vector3d bulged(const Eigen::Vector3d& X) {
  return X + Eigen::Vector3d(0.0, 0.1 * std::sin(M_PI * X.x()), 0.0);
}

TEST(MaterialPointDistance, AnAffineShapeLooksTheSameAtEveryResolution) {
  const MaterialSurface coarse = sheet(4, GridCells::quads, sheared_and_lifted);
  const MaterialSurface fine = sheet(13, GridCells::triangles, sheared_and_lifted);
  const ShapeDistance d = material_point_distance(coarse, fine);
  EXPECT_EQ(d.points, 14 * 14);
  EXPECT_LT(d.max_m, 1e-12);
}

TEST(MaterialPointPositions, AnyRestPointIsFoundWhereTheMeshCarriesIt) {
  // an affine shape: every material point, a vertex or not, lands where the map puts it
  const MaterialSurface coarse = sheet(4, GridCells::triangles, sheared_and_lifted);
  const std::vector<Eigen::Vector3d> points = {
      {0.0, 0.0, 0.0}, {0.37, 0.0, 0.21}, {1.0, 0.0, 0.5}, {0.5, 0.0, 0.499}};
  const std::vector<Eigen::Vector3d> found = material_point_positions(coarse, points);
  ASSERT_EQ(found.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_LT((found[i] - sheared_and_lifted(points[i])).norm(), 1e-12) << "point " << i;
  }
  const std::vector<Eigen::Vector3d> one_near = {Eigen::Vector3d::Zero()};
  EXPECT_THROW(material_point_positions(coarse, points, &one_near), std::invalid_argument);
}

TEST(MaterialPointDistance, ATranslationIsMeasuredAtEveryPoint) {
  const MaterialSurface here = sheet(6, GridCells::triangles, sheared_and_lifted);
  const MaterialSurface moved =
      sheet(9, GridCells::triangles, [](const Eigen::Vector3d& X) -> Eigen::Vector3d {
        return sheared_and_lifted(X) + Eigen::Vector3d(0.0, 0.0, 0.25);
      });
  const ShapeDistance d = material_point_distance(here, moved);
  EXPECT_NEAR(d.mean_m, 0.25, 1e-12);
  EXPECT_NEAR(d.max_m, 0.25, 1e-12);
}

TEST(MaterialPointDistance, ACoarseMeshMissesACurvedShapeByItsInterpolationError) {
  // a sine bulge of amplitude 0.1 m sampled every 0.25 m along x: among the fine points, linear
  // interpolation falls shortest at x = 0.375 m, between the samples at 0.25 and 0.5 m
  const MaterialSurface coarse = sheet(4, GridCells::triangles, bulged);
  const MaterialSurface fine = sheet(16, GridCells::triangles, bulged);
  const ShapeDistance d = material_point_distance(coarse, fine);
  const double shortfall_m =
      0.1 * (std::sin(0.375 * M_PI) - 0.5 * (std::sin(0.25 * M_PI) + std::sin(0.5 * M_PI)));
  EXPECT_NEAR(d.max_m, shortfall_m, 1e-12);
  EXPECT_GT(d.mean_m, 0.0);
  EXPECT_LT(d.mean_m, d.max_m);
  EXPECT_LT(material_point_distance(fine, coarse).max_m, 1e-12);  // coarse samples lie on fine
}

/// A 1 m x 0.5 m sheet torn in two along x = 0.5 m (each half has its own vertices there), each
/// half on `cells` x `cells` triangle cells, the left one moved by `left_y_m` across the sheet and
/// the right one by `right_y_m`.
MaterialSurface torn_sheet(int cells, double left_y_m, double right_y_m) {
  MaterialSurface torn;
  for (const double x0_m : {0.0, 0.5}) {
    GridOptions o;
    o.origin = Eigen::Vector3d(x0_m, 0.0, 0.0);
    o.width = 0.5;
    o.height = 0.5;
    o.cells_u = cells;
    o.cells_v = cells;
    o.cells = GridCells::triangles;
    const IndexedMesh half = make_grid_mesh(o);
    const int first = static_cast<int>(torn.rest_m.size());
    for (const Eigen::Vector3d& X : half.vertices) {
      torn.rest_m.push_back(X);
      torn.current.vertices.push_back(
          X + Eigen::Vector3d(0.0, x0_m == 0.0 ? left_y_m : right_y_m, 0.0));
    }
    for (std::vector<int> face : half.faces) {
      for (int& v : face) v += first;
      torn.current.faces.push_back(face);
    }
  }
  return torn;
}

TEST(MaterialPointDistance, BothLipsOfATearHoldItsPoints) {
  // a point on the tear lies on both halves in rest space: it is the nearer lip's point now
  const MaterialSurface apart = torn_sheet(4, 0.0, 0.3);
  EXPECT_LT(material_point_distance(apart, apart).max_m, 1e-12);
  const ShapeDistance d = material_point_distance(torn_sheet(3, 0.0, 0.4), apart);
  EXPECT_NEAR(d.max_m, 0.1, 1e-12);    // the right half's points, those on its lip among them
  EXPECT_NEAR(d.mean_m, 0.05, 1e-12);  // half of the points are the right half's
}

TEST(SurfaceDistanceBetween, TheSameSurfaceIsAtZeroWhereverItsMaterialPointsLie) {
  // the sheet's material points slid along it (x -> x^2 maps [0, 1] onto itself): every point
  // moved, the surface did not
  const auto slid = [](const Eigen::Vector3d& X) -> Eigen::Vector3d {
    return Eigen::Vector3d(X.x() * X.x(), X.y(), X.z());
  };
  const MaterialSurface flat =
      sheet(8, GridCells::triangles, [](const Eigen::Vector3d& X) { return X; });
  const MaterialSurface moved_along = sheet(5, GridCells::quads, slid);
  EXPECT_GT(material_point_distance(moved_along, flat).max_m, 0.2);
  const ShapeDistance d = surface_distance_between(moved_along.current, flat.current);
  EXPECT_LT(d.max_m, 1e-12);
  EXPECT_EQ(d.points, 9 * 9 + 6 * 6);
}

TEST(SurfaceDistanceBetween, ASheetMovedAcrossItselfIsThatFarBothWays) {
  const MaterialSurface flat =
      sheet(4, GridCells::triangles, [](const Eigen::Vector3d& X) { return X; });
  const MaterialSurface lifted = sheet(7, GridCells::triangles, [](const Eigen::Vector3d& X) {
    return Eigen::Vector3d(X + Eigen::Vector3d(0.0, 0.02, 0.0));
  });
  const ShapeDistance d = surface_distance_between(flat.current, lifted.current);
  EXPECT_NEAR(d.mean_m, 0.02, 1e-12);
  EXPECT_NEAR(d.max_m, 0.02, 1e-12);
}

TEST(SurfaceDistanceBetween, AveragesTheTwoDirections) {
  // the sheet's left half against the whole: the half's points all lie on the whole, the whole's
  // points at x > 0.5 m lie x - 0.5 m beyond the half's edge
  const MaterialSurface whole =
      sheet(10, GridCells::triangles, [](const Eigen::Vector3d& X) { return X; });
  GridOptions o;
  o.width = 0.5;
  o.height = 0.5;
  o.cells_u = 3;
  o.cells_v = 3;
  o.cells = GridCells::triangles;
  const ShapeDistance d = surface_distance_between(make_grid_mesh(o), whole.current);
  double beyond_m = 0.0;  // over the whole's 11 x 11 vertices, 0.1 m apart along x
  for (int i = 6; i <= 10; ++i) beyond_m += 11 * (0.1 * i - 0.5);
  EXPECT_NEAR(d.mean_m, 0.5 * (0.0 + beyond_m / (11 * 11)), 1e-12);
  EXPECT_NEAR(d.max_m, 0.5, 1e-12);
  EXPECT_EQ(d.points, 4 * 4 + 11 * 11);
}

TEST(SurfaceDistanceBetween, RefusesASurfaceWithoutFaces) {
  const MaterialSurface flat =
      sheet(2, GridCells::triangles, [](const Eigen::Vector3d& X) { return X; });
  IndexedMesh points_only;
  points_only.vertices = flat.current.vertices;
  EXPECT_THROW(surface_distance_between(points_only, flat.current), MeshError);
  EXPECT_THROW(surface_distance_between(flat.current, points_only), MeshError);
}

TEST(MaterialPointDistance, RefusesSurfacesWithoutFacesOrRestPositions) {
  const MaterialSurface fine = sheet(4, GridCells::triangles, bulged);
  MaterialSurface empty;
  EXPECT_THROW(material_point_distance(empty, fine), std::invalid_argument);
  MaterialSurface missing_rest = fine;
  missing_rest.rest_m.pop_back();
  EXPECT_THROW(material_point_distance(missing_rest, fine), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
