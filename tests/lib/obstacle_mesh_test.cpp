#include "lib/obstacle_mesh.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace tissu {
namespace {

Obstacle sphere(const Eigen::Vector3d& centre, double radius_m) {
  Obstacle o;
  o.shape = ObstacleShape::sphere;
  o.position = centre;
  o.radius_m = radius_m;
  return o;
}

Obstacle capsule(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius_m) {
  Obstacle o;
  o.shape = ObstacleShape::capsule;
  o.position = from;
  o.axis_end = to;
  o.radius_m = radius_m;
  return o;
}

Obstacle box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents_m,
             const Eigen::Matrix3d& rotation) {
  Obstacle o;
  o.shape = ObstacleShape::box;
  o.position = centre;
  o.half_extents_m = half_extents_m;
  o.rotation = rotation;
  return o;
}

Obstacle floor_at(double z) {
  Obstacle o;
  o.position = {0.3, -0.2, z};
  return o;
}

const Eigen::Matrix3d tilted =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();

/// Every face a triangle, every directed edge used once and its reverse once: each edge is shared
/// by exactly two triangles that run it in opposite directions, so the surface is closed and
/// consistently oriented.
void expect_closed_and_consistent(const IndexedMesh& mesh) {
  ASSERT_FALSE(mesh.faces.empty());
  std::map<std::pair<int, int>, int> directed;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    ASSERT_EQ(face.size(), 3u) << "face " << f;
    for (int i = 0; i < 3; ++i) {
      ASSERT_GE(face[i], 0);
      ASSERT_LT(face[i], static_cast<int>(mesh.vertices.size()));
      ++directed[{face[i], face[(i + 1) % 3]}];
    }
    const Eigen::Vector3d& a = mesh.vertices[face[0]];
    const double area = (mesh.vertices[face[1]] - a).cross(mesh.vertices[face[2]] - a).norm() / 2.0;
    EXPECT_GT(area, 0.0) << "degenerate face " << f;
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " run " << count
                        << " times in one direction";
    const auto reverse = directed.find({edge.second, edge.first});
    EXPECT_TRUE(reverse != directed.end() && reverse->second == 1)
        << "edge " << edge.first << "-" << edge.second << " has no opposite half";
  }
}

/// The enclosed volume (m^3) by the divergence theorem: positive when faces are counter-clockwise
/// seen from outside (outward normals).
double signed_volume(const IndexedMesh& mesh) {
  double six_volume = 0.0;
  for (const std::vector<int>& f : mesh.faces)
    six_volume += mesh.vertices[f[0]].dot(mesh.vertices[f[1]].cross(mesh.vertices[f[2]]));
  return six_volume / 6.0;
}

/// Largest |signed distance| (m) of the mesh's vertices to the obstacle's surface at `time_s`.
double largest_vertex_gap(const IndexedMesh& mesh, const Obstacle& obstacle, double time_s) {
  double gap = 0.0;
  for (const Eigen::Vector3d& v : mesh.vertices)
    gap = std::max(gap, std::abs(surface_distance(obstacle, v, time_s).distance_m));
  return gap;
}

/// Largest |signed distance| (m) of the face centroids to the surface: how far the flat
/// triangles sag inside a curved surface.
double largest_centroid_gap(const IndexedMesh& mesh, const Obstacle& obstacle, double time_s) {
  double gap = 0.0;
  for (const std::vector<int>& f : mesh.faces) {
    const Eigen::Vector3d c = (mesh.vertices[f[0]] + mesh.vertices[f[1]] + mesh.vertices[f[2]]) / 3;
    gap = std::max(gap, std::abs(surface_distance(obstacle, c, time_s).distance_m));
  }
  return gap;
}

TEST(ObstacleMesh, SphereIsClosedOutwardOnTheSurfaceAndRound) {
  const Obstacle ball = sphere({0.1, -0.2, 0.35}, 0.35);
  const IndexedMesh mesh = obstacle_mesh(ball, 0.0);
  expect_closed_and_consistent(mesh);
  EXPECT_LT(largest_vertex_gap(mesh, ball, 0.0), 1e-12);
  const double r = ball.radius_m;
  EXPECT_NEAR(signed_volume(mesh), 4.0 / 3.0 * std::numbers::pi * r * r * r,
              0.01 * 4.0 / 3.0 * std::numbers::pi * r * r * r);
  // round at 720 pixels: the flat faces sag less than 0.3 % of the radius (1 pixel in 360)
  EXPECT_LT(largest_centroid_gap(mesh, ball, 0.0), 3e-3 * r);
}

TEST(ObstacleMesh, CapsuleIsAClosedCylinderWithHemisphericalEnds) {
  const Obstacle rod = capsule({-0.4, 0.1, 0.2}, {0.5, 0.3, 0.6}, 0.12);
  const IndexedMesh mesh = obstacle_mesh(rod, 0.0);
  expect_closed_and_consistent(mesh);
  EXPECT_LT(largest_vertex_gap(mesh, rod, 0.0), 1e-12);
  const double r = rod.radius_m, length = (rod.axis_end - rod.position).norm();
  const double volume =
      std::numbers::pi * r * r * length + 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(signed_volume(mesh), volume, 0.01 * volume);
  EXPECT_LT(largest_centroid_gap(mesh, rod, 0.0), 3e-3 * r);
  // both caps reach their ends: the farthest vertices along the axis are r beyond each end
  const Eigen::Vector3d axis = (rod.axis_end - rod.position).normalized();
  double low = 0.0, high = 0.0;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    low = std::min(low, (v - rod.position).dot(axis));
    high = std::max(high, (v - rod.position).dot(axis));
  }
  EXPECT_NEAR(low, -r, 1e-12);
  EXPECT_NEAR(high, length + r, 1e-12);
}

TEST(ObstacleMesh, CapsuleAlongZAndOfZeroLengthStayClosed) {
  // an axis along z (the first perpendicular candidate changes) and a capsule that is a ball
  for (const Obstacle& rod :
       {capsule({0, 0, 0}, {0, 0, 1}, 0.2), capsule({1, 1, 1}, {1, 1, 1}, 0.2)}) {
    const IndexedMesh mesh = obstacle_mesh(rod, 0.0);
    expect_closed_and_consistent(mesh);
    EXPECT_GT(signed_volume(mesh), 0.0);
    EXPECT_LT(largest_vertex_gap(mesh, rod, 0.0), 1e-12);
  }
}

TEST(ObstacleMesh, RotatedBoxHasEightCornersAndTwelveFlatOutwardTriangles) {
  const Obstacle block = box({0.2, 0.1, -0.3}, {0.3, 0.1, 0.2}, tilted);
  const IndexedMesh mesh = obstacle_mesh(block, 0.0);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.faces.size(), 12u);
  expect_closed_and_consistent(mesh);
  EXPECT_NEAR(signed_volume(mesh), 8 * 0.3 * 0.1 * 0.2, 1e-12);
  // corners and face centroids on the surface: the faces are the box's, not cut across it
  EXPECT_LT(largest_vertex_gap(mesh, block, 0.0), 1e-12);
  EXPECT_LT(largest_centroid_gap(mesh, block, 0.0), 1e-12);
  // each triangle faces out along one of the rotated axes
  for (const std::vector<int>& f : mesh.faces) {
    const Eigen::Vector3d& a = mesh.vertices[f[0]];
    const Eigen::Vector3d n = (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).normalized();
    const Eigen::Vector3d c = (a + mesh.vertices[f[1]] + mesh.vertices[f[2]]) / 3.0;
    EXPECT_NEAR((tilted.transpose() * n).cwiseAbs().maxCoeff(), 1.0, 1e-12);
    EXPECT_TRUE(n.isApprox(surface_distance(block, c, 0.0).normal, 1e-12)) << n.transpose();
  }
}

TEST(ObstacleMesh, FollowsTheObstacleMotion) {
  for (Obstacle o : {sphere({0, 0, 0.5}, 0.3), capsule({0, 0, 0}, {0.4, 0, 0.2}, 0.1),
                     box({0, 0, 0}, {0.2, 0.3, 0.1}, tilted)}) {
    o.motion.keys = {{0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                     {1.0, Eigen::Vector3d(0.0, 0.0, 0.8), Eigen::Vector3d::Zero()}};
    o.motion.drift_m_per_s = {0.5, 0.0, 0.0};
    const double t = 0.5;  // offset (0.25, 0, 0.4)
    const IndexedMesh at_rest = obstacle_mesh(o, 0.0), moved = obstacle_mesh(o, t);
    ASSERT_EQ(moved.vertices.size(), at_rest.vertices.size());
    EXPECT_EQ(moved.faces, at_rest.faces);
    for (std::size_t v = 0; v < moved.vertices.size(); ++v)
      EXPECT_TRUE(
          moved.vertices[v].isApprox(at_rest.vertices[v] + Eigen::Vector3d(0.25, 0.0, 0.4), 1e-12));
    EXPECT_LT(largest_vertex_gap(moved, o, t), 1e-12);
    EXPECT_GT(largest_vertex_gap(moved, o, 0.0), 0.05);  // not where it started
  }
}

TEST(ObstacleMesh, PlanesAreNotMeshed) {
  EXPECT_TRUE(obstacle_mesh(floor_at(0.0), 0.0).vertices.empty());
  EXPECT_TRUE(obstacle_mesh(floor_at(0.0), 0.0).faces.empty());
}

TEST(GroundHeight, IsTheHighestUpwardPlaneWhereItHasMovedTo) {
  EXPECT_FALSE(ground_height_m({}, 0.0));
  EXPECT_FALSE(ground_height_m({sphere({0, 0, 0}, 1.0)}, 0.0));

  Obstacle wall;
  wall.position = {0.0, 0.0, 5.0};
  wall.normal = {1.0, 0.0, 0.0};
  Obstacle ceiling = floor_at(3.0);
  ceiling.normal = {0.0, 0.0, -1.0};
  EXPECT_FALSE(ground_height_m({wall, ceiling}, 0.0)) << "only planes facing +z are ground";

  Obstacle rising = floor_at(-1.0);
  rising.motion.drift_m_per_s = {0.0, 0.0, 2.0};
  const std::vector<Obstacle> scene{wall, floor_at(0.25), rising, ceiling};
  EXPECT_EQ(ground_height_m(scene, 0.0), 0.25);
  EXPECT_EQ(ground_height_m(scene, 1.0), 1.0);  // the rising floor is now the higher
}

}  // namespace
}  // namespace tissu
