#pragma once
/// \file
/// Obstacles the cloth cannot enter: analytic shapes and triangle meshes, their rigid motion, a
/// mesh's deformation (an animated body), and their distance field. CGAL-free.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "solver/rigid_motion.hpp"

namespace tissu {

/// The nearest point of an obstacle's surface to a point.
struct SurfaceDistance {
  double distance_m = 0.0;                            ///< signed: negative inside
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, outwards, at the nearest point
  /// a mesh's nearest point: its triangle (in SurfaceQuery::triangle_corners' order, -1 for the
  /// analytic shapes) and its barycentric coordinates there
  int triangle = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

/// The distance field of a surface held elsewhere (a triangle mesh, built in topology/ with
/// CGAL), in its own frame: the solver only queries it.
class SurfaceQuery {
 public:
  virtual ~SurfaceQuery() = default;
  /// Signed distance from x (m) to the surface (negative inside a closed one) and its normal.
  virtual SurfaceDistance distance(const Eigen::Vector3d& x_m) const = 0;
  /// The nearest point alone: distance() with its sign (and the normal's) left unsettled, which
  /// spares a closed mesh its inside test (a ray's crossings); the triangle and the
  /// barycentric coordinates are distance()'s.
  virtual SurfaceDistance nearest(const Eigen::Vector3d& x_m) const { return distance(x_m); }
  /// A lower bound on |distance(x_m)| (m) that costs next to nothing: 0 unless a surface knows
  /// better (a mesh: the distance to its bounding box, less a nanometre for round-off).
  virtual double distance_at_least_m(const Eigen::Vector3d& /*x_m*/) const { return 0.0; }
  /// Its triangles' corners, three per triangle (m), for drawing.
  virtual const std::vector<Eigen::Vector3d>& triangle_corners() const = 0;
};

/// The point of `surface`'s triangle `triangle` at barycentric coordinates `barycentric` (m).
Eigen::Vector3d point_on(const SurfaceQuery& surface, int triangle,
                         const Eigen::Vector3d& barycentric);

/// A mesh whose vertices move (an animated body): its surface at any instant, the same triangles
/// in the same order at every instant, their corners moving. Held elsewhere (built in topology/
/// with CGAL); the solver only asks for its surface at the instants it needs.
class SurfaceAnimation {
 public:
  virtual ~SurfaceAnimation() = default;
  /// The surface at `time_s`, held before the first sample and after the last. Thread-safe.
  virtual std::shared_ptr<const SurfaceQuery> at(double time_s) const = 0;
  /// The fastest any point of the surface moves over the animation (m/s).
  virtual double fastest_speed_m_per_s() const = 0;
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
  /// mesh: moves its vertices, before `motion` places it (then `surface` is its shape at t = 0);
  /// none for a rigid mesh
  std::shared_ptr<const SurfaceAnimation> animation;
  /// particles are kept at least this far outside the surface (m): the cloth's half thickness
  double thickness_m = 0.005;
  double static_friction = 0.0;   ///< mu_s: sticks while |v_t| <= mu_s dv_n
  double kinetic_friction = 0.0;  ///< mu_k: otherwise |v_t| loses mu_k dv_n
  RigidMotion motion;             ///< from its place at t = 0
};

/// An obstacle where it is at one instant: for the many queries of that instant (a step's
/// contacts), which then place it once.
struct ObstaclePlacement {
  RigidPose pose;  ///< its rigid motion's
  /// a mesh's surface then, in the frame `pose` moves (its animation's, or its fixed one)
  std::shared_ptr<const SurfaceQuery> surface;
};

ObstaclePlacement place(const Obstacle& obstacle, double time_s);

/// Signed distance from `x` (m) to the surface of `obstacle` at time `time_s`, and the outward
/// normal there. Where the normal is not unique (the centre of a sphere, the axis of a capsule,
/// the centre of a box) one of the candidates is returned.
SurfaceDistance surface_distance(const Obstacle& obstacle, const Eigen::Vector3d& x, double time_s);

/// The same with the obstacle where `placement` puts it.
SurfaceDistance surface_distance(const Obstacle& obstacle, const ObstaclePlacement& placement,
                                 const Eigen::Vector3d& x);

/// A lower bound on |surface_distance(obstacle, placement, x)| (m), for skipping a mesh's queries
/// where the answer is known to be "far": a garment's particles are mostly away from a body's
/// arms, whose parts are separate obstacles. 0 for the analytic shapes, which are cheap to query.
double surface_distance_at_least_m(const Obstacle& obstacle, const ObstaclePlacement& placement,
                                   const Eigen::Vector3d& x);

/// Where the point at `x` (m) when `obstacle` is at `before` would be when it is at `after`, had it
/// moved with the obstacle's surface: its rigid motion carries it, and an animated mesh's nearest
/// point's displacement carries it too. Measuring a particle's path from there measures it
/// relative to the obstacle, so a surface that sweeps over a still particle is seen to reach it.
Eigen::Vector3d carry_with_surface(const Obstacle& obstacle, const ObstaclePlacement& before,
                                   const ObstaclePlacement& after, const Eigen::Vector3d& x);

/// Velocity of the obstacle's surface at `x` (m/s), `nearest` being x's nearest point at `after`
/// (time `time_s`): its rigid motion's point velocity, plus for an animated mesh the mean
/// velocity of that point of its triangle over the `duration_s` from `before` to `after`.
Eigen::Vector3d surface_velocity(const Obstacle& obstacle, const ObstaclePlacement& before,
                                 const ObstaclePlacement& after, const SurfaceDistance& nearest,
                                 const Eigen::Vector3d& x, double time_s, double duration_s);

}  // namespace tissu
