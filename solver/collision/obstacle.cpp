#include "solver/collision/obstacle.hpp"

#include <algorithm>
#include <cmath>

#include "solver/collision/primitive_distance.hpp"

namespace tissu {
namespace {

/// The normal given where every direction is as near (the centre of a sphere, a capsule's axis).
const Eigen::Vector3d fallback_normal = Eigen::Vector3d::UnitZ();

SurfaceDistance from_core(const Eigen::Vector3d& x, const Eigen::Vector3d& core, double radius_m) {
  const Eigen::Vector3d out = x - core;
  const double r = out.norm();
  return {r - radius_m, r > 0.0 ? Eigen::Vector3d(out / r) : fallback_normal};
}

SurfaceDistance box_distance(const Obstacle& box, const Eigen::Vector3d& centre,
                             const Eigen::Vector3d& x) {
  const Eigen::Vector3d q = box.rotation.transpose() * (x - centre);  // in the box's frame
  const Eigen::Vector3d beyond = q.cwiseAbs() - box.half_extents_m;   // > 0: outside that slab
  if ((beyond.array() > 0.0).any()) {
    const Eigen::Vector3d gap = beyond.cwiseMax(0.0).cwiseProduct(q.cwiseSign());
    return {gap.norm(), box.rotation * gap.normalized()};
  }
  // inside: out through the nearest face
  Eigen::Index axis = 0;
  const double depth = beyond.maxCoeff(&axis);
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  local[axis] = q[axis] < 0.0 ? -1.0 : 1.0;
  return {depth, box.rotation * local};
}

/// The distance to `obstacle` translated by `offset` (m) from its place at t = 0; a mesh's surface
/// is `surface`.
SurfaceDistance translated_distance(const Obstacle& obstacle, const SurfaceQuery* surface,
                                    const Eigen::Vector3d& x, const Eigen::Vector3d& offset) {
  const Eigen::Vector3d position = obstacle.position + offset;
  switch (obstacle.shape) {
    case ObstacleShape::plane:
      return {(x - position).dot(obstacle.normal), obstacle.normal};
    case ObstacleShape::sphere:
      return from_core(x, position, obstacle.radius_m);
    case ObstacleShape::capsule: {
      const Eigen::Vector3d end = obstacle.axis_end + offset;
      const Eigen::Vector3d core =
          position + nearest_on_segment(x, position, end) * (end - position);
      return from_core(x, core, obstacle.radius_m);
    }
    case ObstacleShape::box:
      return box_distance(obstacle, position, x);
    case ObstacleShape::mesh:
      return surface->distance(x - offset);
  }
  return {};
}

}  // namespace

Eigen::Vector3d point_on(const SurfaceQuery& surface, int triangle,
                         const Eigen::Vector3d& barycentric) {
  const std::vector<Eigen::Vector3d>& corners = surface.triangle_corners();
  return barycentric[0] * corners[3 * triangle] + barycentric[1] * corners[3 * triangle + 1] +
         barycentric[2] * corners[3 * triangle + 2];
}

ObstaclePlacement place(const Obstacle& obstacle, double time_s) {
  return {obstacle.motion.pose(time_s),
          obstacle.animation ? obstacle.animation->at(time_s) : obstacle.surface};
}

SurfaceDistance surface_distance(const Obstacle& obstacle, const Eigen::Vector3d& x,
                                 double time_s) {
  return surface_distance(obstacle, place(obstacle, time_s), x);
}

SurfaceDistance surface_distance(const Obstacle& obstacle, const ObstaclePlacement& placement,
                                 const Eigen::Vector3d& x) {
  const RigidPose& pose = placement.pose;
  const SurfaceQuery* surface = placement.surface.get();
  if (pose.rotation == Eigen::Matrix3d::Identity()) {
    return translated_distance(obstacle, surface, x, pose.translation_m);
  }
  // measured in the obstacle's place at t = 0, the normal turned with it
  SurfaceDistance at_rest =
      translated_distance(obstacle, surface, pose.apply_inverse(x), Eigen::Vector3d::Zero());
  at_rest.normal = pose.rotation * at_rest.normal;
  return at_rest;
}

double surface_distance_at_least_m(const Obstacle& obstacle, const ObstaclePlacement& placement,
                                   const Eigen::Vector3d& x) {
  if (obstacle.shape != ObstacleShape::mesh) return 0.0;
  // in the mesh's own frame, where surface_distance() measures it (to round-off, which the bound's
  // nanometre covers)
  return placement.surface->distance_at_least_m(placement.pose.apply_inverse(x));
}

Eigen::Vector3d carry_with_surface(const Obstacle& obstacle, const ObstaclePlacement& before,
                                   const ObstaclePlacement& after, const Eigen::Vector3d& x) {
  Eigen::Vector3d local = before.pose.apply_inverse(x);         // in the obstacle's own frame
  if (obstacle.animation && before.surface != after.surface) {  // else its shape held still
    const SurfaceDistance nearest = before.surface->nearest(local);
    if (nearest.triangle >= 0) {
      local += point_on(*after.surface, nearest.triangle, nearest.barycentric) -
               point_on(*before.surface, nearest.triangle, nearest.barycentric);
    }
  }
  return after.pose.apply(local);
}

Eigen::Vector3d surface_velocity(const Obstacle& obstacle, const ObstaclePlacement& before,
                                 const ObstaclePlacement& after, const SurfaceDistance& nearest,
                                 const Eigen::Vector3d& x, double time_s, double duration_s) {
  Eigen::Vector3d velocity = obstacle.motion.point_velocity(x, time_s);
  if (obstacle.animation && before.surface != after.surface && nearest.triangle >= 0) {
    const Eigen::Vector3d moved_m =
        point_on(*after.surface, nearest.triangle, nearest.barycentric) -
        point_on(*before.surface, nearest.triangle, nearest.barycentric);
    velocity += after.pose.rotation * moved_m / duration_s;
  }
  return velocity;
}

}  // namespace tissu
