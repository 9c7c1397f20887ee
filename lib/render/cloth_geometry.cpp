#include "lib/render/cloth_geometry.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "lib/render/vertex_normals.hpp"

namespace tissu {
namespace {

void check_scene(const RenderScene& scene) {
  if (!scene.mesh) throw std::invalid_argument("render scene: no mesh");
  const IndexedMesh& mesh = *scene.mesh;
  const std::size_t vertex_count = mesh.vertices.size();
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (!mesh.vertices[v].allFinite())
      throw std::invalid_argument("render scene: vertex " + std::to_string(v) +
                                  " has a non-finite position");
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    if (face.size() < 3)
      throw std::invalid_argument("render scene: face " + std::to_string(f) + " has " +
                                  std::to_string(face.size()) + " vertices, expected 3 or 4");
    for (int v : face) {
      if (v < 0 || static_cast<std::size_t>(v) >= vertex_count)
        throw std::invalid_argument("render scene: face " + std::to_string(f) + " uses vertex " +
                                    std::to_string(v) + " of " + std::to_string(vertex_count));
    }
  }
  if (!scene.pinned.empty() && scene.pinned.size() != vertex_count)
    throw std::invalid_argument("render scene: " + std::to_string(scene.pinned.size()) +
                                " pin flags for " + std::to_string(vertex_count) + " vertices");
  if (!scene.face_strain.empty() && scene.face_strain.size() != mesh.faces.size())
    throw std::invalid_argument("render scene: " + std::to_string(scene.face_strain.size()) +
                                " face strains for " + std::to_string(mesh.faces.size()) +
                                " faces");
  if (!scene.face_level.empty() && scene.face_level.size() != mesh.faces.size())
    throw std::invalid_argument("render scene: " + std::to_string(scene.face_level.size()) +
                                " face levels for " + std::to_string(mesh.faces.size()) + " faces");
  if (!scene.face_sizing_term.empty() && scene.face_sizing_term.size() != mesh.faces.size())
    throw std::invalid_argument("render scene: " + std::to_string(scene.face_sizing_term.size()) +
                                " face sizing terms for " + std::to_string(mesh.faces.size()) +
                                " faces");
}

void append(std::vector<float>& out, const Eigen::Vector3d& p) {
  out.insert(out.end(),
             {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
}

}  // namespace

ClothGeometry cloth_geometry(const RenderScene& scene, ColorMode mode) {
  check_scene(scene);
  const IndexedMesh& mesh = *scene.mesh;
  const std::vector<Eigen::Vector3f> normals = vertex_normals(mesh);
  ClothGeometry geometry;

  std::vector<std::pair<int, int>> edges;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    const std::vector<float>& values = mode == ColorMode::level         ? scene.face_level
                                       : mode == ColorMode::sizing_term ? scene.face_sizing_term
                                                                        : scene.face_strain;
    const float strain = values.empty() ? 0.0f : values[f];
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      for (int v : {face[0], face[i], face[i + 1]}) {
        append(geometry.triangles, mesh.vertices[v]);
        geometry.triangles.insert(geometry.triangles.end(),
                                  {normals[v].x(), normals[v].y(), normals[v].z(), strain});
      }
    }
    for (std::size_t i = 0; i < face.size(); ++i) {
      const int a = face[i], b = face[(i + 1) % face.size()];
      edges.emplace_back(std::min(a, b), std::max(a, b));
      geometry.bounds.extend(mesh.vertices[a]);
    }
  }

  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  geometry.edges.reserve(6 * edges.size());
  for (const auto& [a, b] : edges) {
    append(geometry.edges, mesh.vertices[a]);
    append(geometry.edges, mesh.vertices[b]);
  }

  for (std::size_t v = 0; v < scene.pinned.size(); ++v) {
    if (!scene.pinned[v]) continue;
    append(geometry.pins, mesh.vertices[v]);
    geometry.bounds.extend(mesh.vertices[v]);
  }
  return geometry;
}

}  // namespace tissu
