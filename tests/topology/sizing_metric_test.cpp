// The anisotropic sizing metric (topology/sizing_metric.hpp): a fold wants short edges across it
// and leaves them free along it, by the shape operator's formula; a flat sheet, or a curved rest
// shape at rest, wants nothing.
#include "topology/sizing_metric.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "cloth_test_support.hpp"
#include "topology/sizing_geometry.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;
constexpr double pi = 3.14159265358979323846;
constexpr double crease_x_m = 0.95;  // a grid line of test::grid(12, 8, ...): 0.2 + 6 x 0.125

/// The metric's eigenvalues (ascending) and eigenvectors in the plane of the face of `d`.
Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> decomposed(const ClothComplex& lcc,
                                                          Dart_const_handle d) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(lcc.info<2>(d).sizing_metric_per_m2);
}

TEST(SizingMetric, AFoldWantsShortEdgesAcrossItAndLeavesThemLongAlongIt) {
  const SpringSettings springs = test::all_springs();
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(test::grid(12, 8, GridCells::triangles)), density_kg_per_m2,
                      springs, lcc);
  // folded by 90 degrees about the line x = crease_x_m (in the x-z plane)
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& r = v->info().rest_position;
    if (r.x() > crease_x_m) v->point() = Point3(crease_x_m, r.y() + (r.x() - crease_x_m), r.z());
  }
  RefinementOptions options;
  options.curvature_threshold_rad = 0.5;
  options.max_aspect_ratio = 4.0;
  options.min_edge_length_m = 1e-3;
  compute_sizing_metric(lcc, options, {});

  int beside = 0;
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    // the face's edge on the crease, if it has one
    Dart_const_handle on_crease = nullptr;
    for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
      const double xa = lcc.vertex_attribute(e)->info().rest_position.x();
      const double xb = lcc.vertex_attribute(lcc.next(e))->info().rest_position.x();
      if (std::abs(xa - crease_x_m) < 1e-9 && std::abs(xb - crease_x_m) < 1e-9) on_crease = e;
    }
    const auto metric = decomposed(lcc, d);
    if (on_crease == nullptr) {
      // a face with no edge on the crease has no folded edge: it wants nothing
      EXPECT_LT(metric.eigenvalues().maxCoeff(), 1e-9);
      continue;
    }
    ++beside;
    // S = theta |e| / (2 A) across the edge, theta = pi / 2, so (S / threshold)^2 across the
    // crease (x) and that over max_aspect^2 along it (z)
    const double edge_m = 0.9 / 8.0;
    const double area_m2 = 0.5 * (1.5 / 12.0) * edge_m;
    const double across_per_m = (pi / 2.0) * edge_m / (2.0 * area_m2);
    const double largest = across_per_m * across_per_m / (0.5 * 0.5);
    EXPECT_NEAR(metric.eigenvalues()[2], largest, 1e-9 * largest);
    EXPECT_NEAR(metric.eigenvalues()[1], largest / 16.0, 1e-9 * largest);
    EXPECT_NEAR(std::abs(metric.eigenvectors().col(2).x()), 1.0, 1e-9);
    EXPECT_NEAR(lcc.info<2>(d).sizing_per_m2, largest, 1e-9 * largest);
    EXPECT_EQ(lcc.info<2>(d).sizing_term, SizingTerm::curvature);
  }
  EXPECT_EQ(beside, 16);  // the 8 cells along the crease each side have a face on it
}

TEST(SizingMetric, ARestShapeCurvedOrFlatWantsNothingAtRest) {
  const SpringSettings springs = test::all_springs();
  IndexedMesh rolled = make_grid_mesh(test::grid(12, 8, GridCells::triangles));
  for (Eigen::Vector3d& x : rolled.vertices) {
    const double angle = (x.x() - 0.2) / 0.3;
    x = Eigen::Vector3d(0.2 + 0.3 * std::sin(angle), -0.1 + 0.3 * (1.0 - std::cos(angle)), x.z());
  }
  for (const IndexedMesh& mesh :
       {rolled, make_grid_mesh(test::grid(12, 8, GridCells::triangles))}) {
    ClothComplex lcc;
    build_cloth_complex(mesh, density_kg_per_m2, springs, lcc);
    RefinementOptions options;
    options.curvature_threshold_rad = 0.1;
    options.strain_threshold = 0.01;
    options.lookahead_s = 0.1;
    compute_sizing_metric(lcc, options, {});
    for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
      EXPECT_LT(f->info().sizing_metric_per_m2.norm(), 1e-12);
      EXPECT_EQ(f->info().sizing_term, SizingTerm::none);
    }
  }
}

TEST(SizingMetric, TheObstacleTermIsNothingFlatOnAFloorAndTheIsotropicTermAsATensor) {
  const SpringSettings springs = test::all_springs();
  // the sheet lies horizontal, 2 mm above a floor of 2 mm thickness
  GridOptions flat = test::grid(12, 8, GridCells::triangles);
  flat.v_axis = Eigen::Vector3d::UnitY();
  flat.origin = Eigen::Vector3d(0.0, 0.0, 0.002);
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(flat), density_kg_per_m2, springs, lcc);
  std::vector<Obstacle> floor(1);
  floor[0].thickness_m = 0.002;
  const SizingInputs inputs{&floor, 0.0};
  RefinementOptions options;  // the obstacle term alone
  options.min_edge_length_m = 1e-4;
  options.max_aspect_ratio = 1e3;  // so that clamping changes the trace by 1e-6 at most
  compute_sizing_metric(lcc, options, inputs);
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    EXPECT_LT(f->info().sizing_metric_per_m2.norm(), 1e-12);
  }
  // tilted by 0.2 rad about its edge x = 0, which stays on the floor: the faces near that edge
  // come down on it, and the metric's trace is the isotropic field's obstacle term
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    v->point() = Point3(p.x() * std::cos(0.2), p.y(), 0.002 + p.x() * std::sin(0.2));
  }
  compute_sizing_metric(lcc, options, inputs);
  std::vector<double> traces;
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    traces.push_back(f->info().sizing_metric_per_m2.trace());
  }
  compute_sizing(lcc, options, inputs);
  int near = 0;
  std::size_t k = 0;
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f, ++k) {
    EXPECT_NEAR(traces[k], f->info().sizing_per_m2, 1e-6 * f->info().sizing_per_m2 + 1e-12);
    near += f->info().sizing_per_m2 > 1.0 ? 1 : 0;
  }
  EXPECT_GT(near, 0);
}

TEST(SizingGeometry, WrappedGivesWhatRemainderGivesWhereverTheAngleIs) {
  // wrapped() takes one exact subtraction within 9 rad and falls back on remainder() beyond: the
  // same value either way (a zero's sign aside: -2 pi gives +0, remainder() -0), the ends of each
  // branch included
  const double angles[] = {0.0,
                           -0.0,
                           1.0,
                           pi,
                           -pi,
                           std::nextafter(pi, 4.0),
                           2.0 * pi,
                           -2.0 * pi,
                           9.0,
                           -9.0,
                           std::nextafter(9.0, 0.0),
                           3.0 * pi,
                           -3.0 * pi,
                           25.0,
                           -25.0};
  for (double angle : angles) {
    EXPECT_EQ(wrapped(angle), std::remainder(angle, 2.0 * pi)) << angle;
  }
  for (int k = -3000; k <= 3000; ++k) {  // a sweep over -3 pi to 3 pi and a little beyond
    const double angle = k * 0.00325;    // rad
    EXPECT_EQ(wrapped(angle), std::remainder(angle, 2.0 * pi)) << angle;
  }
  EXPECT_TRUE(std::isnan(wrapped(std::nan(""))));
}

}  // namespace
}  // namespace tissu
