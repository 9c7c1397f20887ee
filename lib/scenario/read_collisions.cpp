#include "lib/scenario/read_collisions.hpp"

#include <Eigen/Geometry>
#include <limits>
#include <string>

#include "lib/scenario/read_mesh_obstacle.hpp"
#include "lib/scenario/read_motion.hpp"
#include "lib/scenario/scenario_limits.hpp"

namespace tissu {
namespace {

/// Where an obstacle's rotations turn about unless its motion says: its centre (a sphere's or a
/// box's), the first end of a capsule's axis, a plane's point, the mean of a mesh's corners.
Eigen::Vector3d default_pivot(const Obstacle& obstacle) {
  if (obstacle.shape != ObstacleShape::mesh) return obstacle.position;
  const std::vector<Eigen::Vector3d>& corners = obstacle.surface->triangle_corners();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& corner : corners) sum += corner;
  return corners.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(corners.size()));
}

Obstacle read_obstacle(JsonObjectReader o, std::vector<std::string>& notes) {
  Obstacle ob;
  const std::string type = o.choice("type", {"plane", "sphere", "capsule", "box", "mesh"});
  if (type == "plane") {
    ob.shape = ObstacleShape::plane;
    ob.position = o.vector3_or("point", ob.position);
    ob.normal = o.direction_or("normal", ob.normal);
  } else if (type == "sphere") {
    ob.shape = ObstacleShape::sphere;
    ob.position = o.vector3("center");
    ob.radius_m = o.number("radius", positive(" (m)"));
  } else if (type == "capsule") {
    ob.shape = ObstacleShape::capsule;
    ob.position = o.vector3("from");
    ob.axis_end = o.vector3("to");
    ob.radius_m = o.number("radius", positive(" (m)"));
  } else if (type == "mesh") {
    ob.shape = ObstacleShape::mesh;
    read_mesh_obstacle(o, ob, notes);
  } else {
    ob.shape = ObstacleShape::box;
    ob.position = o.vector3("center");
    const std::vector<double> size = o.numbers("size", 3, positive(" (m)"));
    ob.half_extents_m = 0.5 * Eigen::Vector3d(size[0], size[1], size[2]);
    if (o.has("rotation")) ob.rotation = rotation_of(read_rotation_vector(o.object("rotation")));
  }
  ob.thickness_m = o.number_or("thickness", ob.thickness_m, non_negative(" (m)"));
  ob.static_friction = o.number_or("static_friction", 0.0, non_negative(""));
  ob.kinetic_friction = o.number_or("kinetic_friction", ob.static_friction,
                                    between(0.0, ob.static_friction, " (at most static_friction)"));
  if (o.has("motion")) ob.motion = read_motion(o.object("motion"), default_pivot(ob));
  o.finish();
  return ob;
}

}  // namespace

std::vector<Obstacle> read_obstacles(JsonObjectReader& top, std::vector<std::string>& notes) {
  std::vector<Obstacle> obstacles;
  if (!top.has("obstacles")) return obstacles;
  for (const ArrayElement& element : top.array("obstacles")) {
    obstacles.push_back(read_obstacle(object_reader(element, top.file()), notes));
  }
  return obstacles;
}

SelfCollisionOptions read_self_collision(JsonObjectReader self_collision) {
  SelfCollisionOptions o;
  o.enabled = self_collision.boolean_or("enabled", true);
  o.thickness_m = self_collision.number_or("thickness", o.thickness_m, positive(" (m)"));
  o.friction = self_collision.number_or("friction", o.friction, non_negative(""));
  o.impulse_passes = self_collision.integer_or("impulse_passes", o.impulse_passes, 0, 1000);
  o.skin_m = self_collision.number_or("skin", o.skin_m, non_negative(" (m)"));
  self_collision.finish();
  return o;
}

}  // namespace tissu
