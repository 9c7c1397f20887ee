#include "lib/render/obstacle_geometry.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "lib/render/cloth_geometry.hpp"
#include "lib/render/vertex_normals.hpp"

namespace tissu {
namespace {

void check_obstacle(const IndexedMesh& mesh, std::size_t index) {
  const std::string name = "render scene: obstacle " + std::to_string(index);
  const std::size_t vertex_count = mesh.vertices.size();
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (!mesh.vertices[v].allFinite())
      throw std::invalid_argument(name + ": vertex " + std::to_string(v) +
                                  " has a non-finite position");
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    if (face.size() < 3)
      throw std::invalid_argument(name + ": face " + std::to_string(f) + " has " +
                                  std::to_string(face.size()) + " vertices, expected at least 3");
    for (int v : face) {
      if (v < 0 || static_cast<std::size_t>(v) >= vertex_count)
        throw std::invalid_argument(name + ": face " + std::to_string(f) + " uses vertex " +
                                    std::to_string(v) + " of " + std::to_string(vertex_count));
    }
  }
}

void append_corner(std::vector<float>& out, const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  out.insert(out.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()),
                         static_cast<float>(p.z()), static_cast<float>(n.x()),
                         static_cast<float>(n.y()), static_cast<float>(n.z()), 0.0f});
}

void append_mesh(const IndexedMesh& mesh, ObstacleGeometry& geometry) {
  const double cos_crease = std::cos(obstacle_crease_angle_deg * std::numbers::pi / 180.0);
  std::vector<Eigen::Vector3d> areas, units;
  std::vector<std::vector<int>> faces_at(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    areas.push_back(face_vector_area(mesh, mesh.faces[f]));
    const double length = areas.back().norm();
    // a degenerate face joins no neighbour's normal and gets none of its own
    units.push_back(length > 0.0 ? Eigen::Vector3d(areas.back() / length)
                                 : Eigen::Vector3d::Zero());
    for (int v : mesh.faces[f]) faces_at[v].push_back(static_cast<int>(f));
  }
  const auto corner_normal = [&](std::size_t f, int v) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int g : faces_at[v]) {
      if (units[g].dot(units[f]) >= cos_crease) sum += areas[g];
    }
    const double length = sum.norm();
    // zero: the shader falls back to the face's own normal
    return length > 0.0 ? Eigen::Vector3d(sum / length) : Eigen::Vector3d::Zero();
  };
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      for (int v : {face[0], face[i], face[i + 1]})
        append_corner(geometry.triangles, mesh.vertices[v], corner_normal(f, v));
    }
    for (int v : face) geometry.bounds.extend(mesh.vertices[v]);
  }
}

}  // namespace

ObstacleGeometry obstacle_geometry(std::span<const IndexedMesh> obstacles) {
  ObstacleGeometry geometry;
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    check_obstacle(obstacles[k], k);
    append_mesh(obstacles[k], geometry);
  }
  static_assert(cloth_vertex_floats == 7, "append_corner writes the cloth's 7-float layout");
  return geometry;
}

}  // namespace tissu
