#include "lib/render/obstacle_geometry.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "lib/render/cloth_geometry.hpp"
#include "render_test_support.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

Eigen::Vector3f corner_position(const ObstacleGeometry& g, int corner) {
  return Eigen::Vector3f::Map(&g.triangles[cloth_vertex_floats * corner]);
}

Eigen::Vector3f corner_normal(const ObstacleGeometry& g, int corner) {
  return Eigen::Vector3f::Map(&g.triangles[cloth_vertex_floats * corner + 3]);
}

/// Two triangles sharing the edge (0,0,0)-(0,1,0): one in the plane z = 0, the other folded
/// down by `fold_deg` beyond the edge, both facing up when the fold is 0.
IndexedMesh hinge(double fold_deg) {
  const double a = fold_deg * std::numbers::pi / 180.0;
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {0, 1, 0}, {-1, 0.5, 0}, {std::cos(a), 0.5, -std::sin(a)}};
  mesh.faces = {{0, 1, 2}, {0, 3, 1}};
  return mesh;
}

TEST(ObstacleGeometry, ACubeIsFlatShadedWithOutwardFaceNormals) {
  const IndexedMesh cube = test::cube_mesh({1.0, 2.0, 3.0}, 0.5);
  const std::vector<IndexedMesh> obstacles{cube};
  const ObstacleGeometry g = obstacle_geometry(obstacles);
  ASSERT_EQ(g.triangles.size(), 36u * cloth_vertex_floats);
  for (int t = 0; t < 12; ++t) {
    const Eigen::Vector3f a = corner_position(g, 3 * t), b = corner_position(g, 3 * t + 1),
                          c = corner_position(g, 3 * t + 2);
    const Eigen::Vector3f face = (b - a).cross(c - a).normalized();
    const Eigen::Vector3f out = (a + b + c) / 3.0f - Eigen::Vector3f(1, 2, 3);
    EXPECT_GT(face.dot(out), 0.0f) << "triangle " << t << " faces in";
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(corner_normal(g, 3 * t + k).isApprox(face, 1e-6f))
          << "triangle " << t << " corner " << k << ": " << corner_normal(g, 3 * t + k).transpose();
      EXPECT_EQ(g.triangles[cloth_vertex_floats * (3 * t + k) + 6], 0.0f);  // no strain
    }
  }
  EXPECT_TRUE(g.bounds.min().isApprox(Eigen::Vector3d(0.5, 1.5, 2.5)));
  EXPECT_TRUE(g.bounds.max().isApprox(Eigen::Vector3d(1.5, 2.5, 3.5)));
}

TEST(ObstacleGeometry, GentleBendsAreSmoothAndSharpOnesKeepTheirCrease) {
  const std::vector<IndexedMesh> gentle{hinge(10.0)}, sharp{hinge(60.0)};
  // corners 0 and 1 of triangle 0 are the shared vertices 0 and 1; triangle 1 meets them at
  // corners 3 (vertex 0) and 5 (vertex 1)
  const ObstacleGeometry smooth = obstacle_geometry(gentle);
  EXPECT_TRUE(corner_normal(smooth, 0).isApprox(corner_normal(smooth, 3), 1e-6f));
  EXPECT_TRUE(corner_normal(smooth, 1).isApprox(corner_normal(smooth, 5), 1e-6f));
  EXPECT_NEAR(corner_normal(smooth, 0).norm(), 1.0f, 1e-6f);
  // the shared normal lies between the two faces': tilted 5 degrees from +z
  EXPECT_NEAR(corner_normal(smooth, 0).z(), std::cos(5.0 * std::numbers::pi / 180.0), 1e-6);
  // the unshared vertex keeps its own face's normal
  EXPECT_TRUE(corner_normal(smooth, 2).isApprox(Eigen::Vector3f::UnitZ(), 1e-6f));

  const ObstacleGeometry creased = obstacle_geometry(sharp);
  EXPECT_TRUE(corner_normal(creased, 0).isApprox(Eigen::Vector3f::UnitZ(), 1e-6f));
  EXPECT_GT((corner_normal(creased, 0) - corner_normal(creased, 3)).norm(), 0.5f);
}

TEST(ObstacleGeometry, ConcatenatesObstaclesAndIsEmptyWithoutAny) {
  const std::vector<IndexedMesh> two{test::cube_mesh({0, 0, 0}, 0.5),
                                     test::cube_mesh({3, 0, 0}, 0.5)};
  const ObstacleGeometry g = obstacle_geometry(two);
  EXPECT_EQ(g.triangles.size(), 72u * cloth_vertex_floats);
  EXPECT_TRUE(g.bounds.max().isApprox(Eigen::Vector3d(3.5, 0.5, 0.5)));
  const ObstacleGeometry none = obstacle_geometry({});
  EXPECT_TRUE(none.triangles.empty());
  EXPECT_TRUE(none.bounds.isEmpty());
}

TEST(ObstacleGeometry, RejectsBadIdsAndPositionsNamingTheObstacle) {
  std::vector<IndexedMesh> obstacles{test::cube_mesh({0, 0, 0}, 0.5),
                                     test::cube_mesh({0, 0, 0}, 0.5)};
  obstacles[1].faces[4] = {0, 1, 8};
  try {
    obstacle_geometry(obstacles);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("obstacle 1: face 4 uses vertex 8 of 8"));
  }
  obstacles[1] = test::cube_mesh({0, 0, 0}, 0.5);
  obstacles[0].vertices[2].x() = std::nan("");
  EXPECT_THROW(obstacle_geometry(obstacles), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
