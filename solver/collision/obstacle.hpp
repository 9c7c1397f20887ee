#pragma once
/// \file
/// Rigid obstacles the cloth cannot enter: analytic shapes, their motion and their distance
/// field. CGAL-free.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "solver/rigid_motion.hpp"

namespace tissu {

/// The nearest point of an obstacle's surface to a point.
struct SurfaceDistance {
  double distance_m = 0.0;                            ///< signed: negative inside
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, outwards, at the nearest point
};

/// The distance field of a surface held elsewhere (a triangle mesh, built in topology/ with
/// CGAL), in its own frame: the solver only queries it.
class SurfaceQuery {
 public:
  virtual ~SurfaceQuery() = default;
  /// Signed distance from x (m) to the surface (negative inside a closed one) and its normal.
  virtual SurfaceDistance distance(const Eigen::Vector3d& x_m) const = 0;
  /// Its triangles' corners, three per triangle (m), for drawing.
  virtual const std::vector<Eigen::Vector3d>& triangle_corners() const = 0;
};

enum class ObstacleShape {
  plane,    ///< the half-space below a plane (a floor)
  sphere,   ///< a ball
  capsule,  ///< the points within a radius of a segment
  box,      ///< a box, rotated or not
  mesh,     ///< a triangle mesh (`surface`)
};

struct Obstacle {
  ObstacleShape shape = ObstacleShape::plane;
  /// plane: a point on it; sphere and box: the centre; capsule: one end of its axis (m), at t = 0
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal{0.0, 0.0, 1.0};                     ///< plane: unit, pointing outside
  Eigen::Vector3d axis_end = Eigen::Vector3d::Zero();        ///< capsule: the other end (m)
  double radius_m = 0.0;                                     ///< sphere and capsule
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();  ///< box, along its own axes
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();    ///< box: its axes as columns
  std::shared_ptr<const SurfaceQuery> surface;  ///< mesh: its distance field, placed at t = 0
  /// particles are kept at least this far outside the surface (m): the cloth's half thickness
  double thickness_m = 0.005;
  double static_friction = 0.0;   ///< mu_s: sticks while |v_t| <= mu_s dv_n
  double kinetic_friction = 0.0;  ///< mu_k: otherwise |v_t| loses mu_k dv_n
  RigidMotion motion;             ///< from its place at t = 0
};

/// Signed distance from `x` (m) to the surface of `obstacle` at time `time_s`, and the outward
/// normal there. Where the normal is not unique (the centre of a sphere, the axis of a capsule,
/// the centre of a box) one of the candidates is returned.
SurfaceDistance surface_distance(const Obstacle& obstacle, const Eigen::Vector3d& x, double time_s);

/// The same with the obstacle placed by `pose`, obstacle.motion.pose(time_s): for the many
/// queries of one instant (a step's contacts), which then place it once.
SurfaceDistance surface_distance(const Obstacle& obstacle, const RigidPose& pose,
                                 const Eigen::Vector3d& x);

}  // namespace tissu
