#include "lib/obstacle_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace tissu {
namespace {

/// A unit vector perpendicular to unit `w`, chosen away from the axis `w` is nearest to, so the
/// cross product stays well conditioned.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& w) {
  const Eigen::Vector3d other =
      std::abs(w.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return w.cross(other).normalized();
}

/// The points within `radius_m` of segment [a, b] (a sphere when a == b): rings of
/// `segments` vertices around the axis from the pole below a to the pole beyond b, a
/// hemisphere of segments / 4 bands at each end and, for a capsule, one cylinder band between.
IndexedMesh capsule_mesh(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius_m,
                         int segments) {
  const Eigen::Vector3d axis = b - a;
  const bool cylinder = axis.norm() > 1e-9 * radius_m;  // else the two rings would coincide
  const Eigen::Vector3d w =
      cylinder ? Eigen::Vector3d(axis.normalized()) : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d u = perpendicular(w), v = w.cross(u);  // u x v = w: right-handed
  const int bands = std::max(segments / 4, 1);                 // per hemisphere

  IndexedMesh mesh;
  // a ring at latitude `phi` (rad, 0 at the equator, +-pi/2 at the poles) around `centre`
  const auto add_ring = [&](const Eigen::Vector3d& centre, double phi) {
    for (int j = 0; j < segments; ++j) {
      const double theta = 2.0 * std::numbers::pi * j / segments;
      mesh.vertices.push_back(
          centre + radius_m * (std::cos(phi) * (std::cos(theta) * u + std::sin(theta) * v) +
                               std::sin(phi) * w));
    }
  };
  const double step = std::numbers::pi / 2.0 / bands;
  mesh.vertices.push_back(a - radius_m * w);  // south pole, vertex 0
  for (int k = 1; k <= bands; ++k) add_ring(a, -std::numbers::pi / 2.0 + k * step);
  if (cylinder) add_ring(b, 0.0);
  for (int k = 1; k < bands; ++k) add_ring(b, k * step);
  mesh.vertices.push_back(b + radius_m * w);  // north pole
  const int rings = (static_cast<int>(mesh.vertices.size()) - 2) / segments;
  const int north = static_cast<int>(mesh.vertices.size()) - 1;

  // counter-clockwise seen from outside: theta grows to the viewer's right, w is up
  const auto ring_vertex = [&](int ring, int j) { return 1 + ring * segments + j % segments; };
  for (int j = 0; j < segments; ++j) {
    mesh.faces.push_back({0, ring_vertex(0, j + 1), ring_vertex(0, j)});
    for (int r = 0; r + 1 < rings; ++r) {
      const int lo = ring_vertex(r, j), lo_next = ring_vertex(r, j + 1);
      const int up = ring_vertex(r + 1, j), up_next = ring_vertex(r + 1, j + 1);
      mesh.faces.push_back({lo, lo_next, up_next});
      mesh.faces.push_back({lo, up_next, up});
    }
    mesh.faces.push_back({ring_vertex(rings - 1, j), ring_vertex(rings - 1, j + 1), north});
  }
  return mesh;
}

/// The 8 corners centre + rotation (+-h), two triangles per face.
IndexedMesh box_mesh(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents_m,
                     const Eigen::Matrix3d& rotation) {
  IndexedMesh mesh;
  // corner i has local coordinate sign (bit 0: x, bit 1: y, bit 2: z), 1 for +
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    mesh.vertices.push_back(centre + rotation * sign.cwiseProduct(half_extents_m));
  }
  // each face counter-clockwise seen from outside (before the rotation)
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5},   // -x, +x
                           {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
                           {0, 2, 3, 1}, {4, 5, 7, 6}};  // -z, +z
  // a reflection (det < 0) would turn the faces inside out: reverse them back
  const bool mirrored = rotation.determinant() < 0.0;
  for (const auto& q : quads) {
    std::vector<int> first{q[0], q[1], q[2]}, second{q[0], q[2], q[3]};
    if (mirrored) {
      std::swap(first[1], first[2]);
      std::swap(second[1], second[2]);
    }
    mesh.faces.push_back(std::move(first));
    mesh.faces.push_back(std::move(second));
  }
  return mesh;
}

/// The obstacle's surface before its rigid motion moves it: its place at t = 0, an animated
/// mesh's shape at `time_s`.
IndexedMesh unmoved_mesh(const Obstacle& obstacle, double time_s) {
  const Eigen::Vector3d& position = obstacle.position;
  switch (obstacle.shape) {
    case ObstacleShape::plane:
      return {};
    case ObstacleShape::sphere:
      return capsule_mesh(position, position, obstacle.radius_m, obstacle_mesh_segments);
    case ObstacleShape::capsule:
      return capsule_mesh(position, obstacle.axis_end, obstacle.radius_m, obstacle_mesh_segments);
    case ObstacleShape::box:
      return box_mesh(position, obstacle.half_extents_m, obstacle.rotation);
    case ObstacleShape::mesh: {
      IndexedMesh mesh;
      mesh.vertices = obstacle.animation ? obstacle.animation->at(time_s)->triangle_corners()
                                         : obstacle.surface->triangle_corners();
      for (int t = 0; 3 * t < static_cast<int>(mesh.vertices.size()); ++t) {
        mesh.faces.push_back({3 * t, 3 * t + 1, 3 * t + 2});
      }
      return mesh;
    }
  }
  return {};
}

}  // namespace

IndexedMesh obstacle_mesh(const Obstacle& obstacle, double time_s) {
  IndexedMesh mesh = unmoved_mesh(obstacle, time_s);
  const RigidPose pose = obstacle.motion.pose(time_s);
  for (Eigen::Vector3d& vertex : mesh.vertices) vertex = pose.apply(vertex);
  return mesh;
}

std::optional<double> ground_height_m(const std::vector<Obstacle>& obstacles, double time_s) {
  std::optional<double> height;
  for (const Obstacle& o : obstacles) {
    if (o.shape != ObstacleShape::plane) continue;
    // a floor: the normal is +z up to rounding (the reader normalises directions)
    if (!(o.normal.normalized().z() > 1.0 - 1e-9) || o.motion.rotates()) continue;
    const double z = o.motion.pose(time_s).apply(o.position).z();
    // the highest floor is the one the cloth can rest on
    height = height ? std::max(*height, z) : z;
  }
  return height;
}

}  // namespace tissu
