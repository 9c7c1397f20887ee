#include "topology/grid_mesh.hpp"

#include <gtest/gtest.h>

namespace tissu {
namespace {

GridOptions pleated_curtain() {
  GridOptions o;
  o.width = 2.0;
  o.height = 1.0;
  o.cells_u = 80;
  o.cells_v = 4;
  o.pleats = 5;
  o.gathered_width = 1.4;
  o.origin = Eigen::Vector3d(-0.7, 0.0, 0.0);
  return o;
}

TEST(GridMesh, VerticesAndFacesFollowTheDocumentedNumbering) {
  GridOptions o;
  o.cells_u = 3;
  o.cells_v = 2;
  o.cells = GridCells::quads;
  const IndexedMesh mesh = make_grid_mesh(o);
  ASSERT_EQ(mesh.vertices.size(), 12u);
  EXPECT_TRUE(mesh.vertices[4 * 1 + 2].isApprox(Eigen::Vector3d(2.0 / 3.0, 0.0, 0.5)));
  ASSERT_EQ(mesh.faces.size(), 6u);
  EXPECT_EQ(mesh.faces[0], (std::vector<int>{0, 1, 5, 4}));
  EXPECT_THROW(make_grid_mesh(GridOptions{.cells_u = 0}), std::invalid_argument);
}

TEST(GridInitialPositions, FlatGridStartsAtItsRestShape) {
  GridOptions o = pleated_curtain();
  o.pleats = 0;
  EXPECT_EQ(grid_initial_positions(o), make_grid_mesh(o).vertices);
}

TEST(GridInitialPositions, PleatsGatherTheWidthAndKeepTheArcLength) {
  const GridOptions o = pleated_curtain();
  const std::vector<Eigen::Vector3d> rest = make_grid_mesh(o).vertices;
  const std::vector<Eigen::Vector3d> start = grid_initial_positions(o);
  ASSERT_EQ(start.size(), rest.size());
  const int nu = o.cells_u + 1;
  double row_length_m = 0.0, amplitude_m = 0.0;
  for (int i = 0; i < nu; ++i) {
    // vertical lines stay vertical and keep their height
    EXPECT_DOUBLE_EQ(start[i].z(), rest[i].z());
    EXPECT_DOUBLE_EQ(start[nu + i].x(), start[i].x());
    amplitude_m = std::max(amplitude_m, std::abs(start[i].y()));
    if (i > 0) row_length_m += (start[i] - start[i - 1]).norm();
  }
  EXPECT_NEAR(start[nu - 1].x() - start[0].x(), o.gathered_width, 1e-12);
  EXPECT_NEAR(start[0].x(), o.origin.x(), 1e-12);
  // the polyline through 81 samples of the sine is a little shorter than its arc length
  EXPECT_NEAR(row_length_m, o.width, 0.01 * o.width);
  EXPECT_GT(amplitude_m, 0.05);
}

TEST(GridInitialPositions, RejectsAGatheredWidthNotBelowTheWidth) {
  GridOptions o = pleated_curtain();
  o.gathered_width = 2.0;
  EXPECT_THROW(grid_initial_positions(o), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
