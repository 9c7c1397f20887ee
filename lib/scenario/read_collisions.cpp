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
Eigen::Vector3d default_pivot(const Obstacle& obstacle, const MeshObstacleParts& mesh) {
  return obstacle.shape == ObstacleShape::mesh ? mesh.centre_m : obstacle.position;
}

/// One obstacle of the scenario: a mesh of several parts gives one obstacle per part (with the
/// same keys), the others one.
std::vector<Obstacle> read_obstacle(JsonObjectReader o, std::vector<std::string>& notes) {
  Obstacle ob;
  MeshObstacleParts mesh;
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
    mesh = read_mesh_obstacle(o, notes);
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
  if (o.has("motion")) ob.motion = read_motion(o.object("motion"), default_pivot(ob, mesh));
  o.finish();
  if (ob.shape != ObstacleShape::mesh) return {ob};
  std::vector<Obstacle> parts(mesh.surfaces.size(), ob);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    parts[k].surface = mesh.surfaces[k];
    if (!mesh.animations.empty()) parts[k].animation = mesh.animations[k];
  }
  return parts;
}

}  // namespace

std::vector<Obstacle> read_obstacles(JsonObjectReader& top, std::vector<std::string>& notes) {
  std::vector<Obstacle> obstacles;
  if (!top.has("obstacles")) return obstacles;
  for (const ArrayElement& element : top.array("obstacles")) {
    for (Obstacle& part : read_obstacle(object_reader(element, top.file()), notes)) {
      obstacles.push_back(std::move(part));
    }
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
