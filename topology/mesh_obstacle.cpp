#include "topology/mesh_obstacle.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "topology/eigen_conversions.hpp"
#include "topology/winding_number.hpp"

namespace tissu {
namespace {

using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

/// The triangles of an obstacle mesh, as vertex ids, after the checks and clean-up
/// make_mesh_surface documents.
struct ObstacleTriangles {
  std::vector<std::array<int, 3>> kept;
  /// zero-area triangles of distinct vertices (collinear corners, e.g. from a fan across a
  /// polygon's straight angle): they hold no area, but their edges belong to the surface's
  /// boundary chain, which they close
  std::vector<std::array<int, 3>> flat;
};

bool has_zero_area(const IndexedMesh& mesh, const std::array<int, 3>& t) {
  const Eigen::Vector3d& a = mesh.vertices[t[0]];
  return (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).squaredNorm() == 0.0;
}

ObstacleTriangles obstacle_triangles(const IndexedMesh& mesh, ObstacleMeshReport& report) {
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  for (int v = 0; v < vertex_count; ++v) {
    if (!mesh.vertices[v].allFinite()) {
      throw MeshError("vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
  }
  if (mesh.faces.empty()) throw MeshError("the mesh has no faces");
  ObstacleTriangles triangles;
  std::set<std::array<int, 3>> seen;  // each triangle rotated to start at its smallest id
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    if (face.size() < 3) {
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                      " vertices; expected at least 3");
    }
    for (int v : face) {
      if (v < 0 || v >= vertex_count) {
        throw MeshError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                        ", but the mesh has " + std::to_string(vertex_count) + " vertices");
      }
    }
    int kept = 0, duplicates = 0;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      std::array<int, 3> t{face[0], face[k], face[k + 1]};
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;  // nothing to the boundary
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      if (!seen.insert(t).second) {
        ++duplicates;
      } else if (has_zero_area(mesh, t)) {
        triangles.flat.push_back(t);
      } else {
        triangles.kept.push_back(t);
        ++kept;
      }
    }
    // a face counts as dropped when none of its triangles is kept (a fan across a straight
    // angle has a flat triangle, but the face itself is fine)
    if (kept == 0) ++(duplicates > 0 ? report.duplicate_faces : report.degenerate_faces);
  }
  if (triangles.kept.empty()) {
    throw MeshError("all " + std::to_string(mesh.faces.size()) +
                    " faces are degenerate (a repeated vertex or zero area)");
  }
  report.triangles = static_cast<int>(triangles.kept.size());
  return triangles;
}

/// Whether every directed edge a->b is matched by as many edges b->a: the triangles then bound
/// a volume (the boundary of their chain is empty) and their winding number is an integer.
bool is_closed(const ObstacleTriangles& triangles) {
  std::map<std::pair<int, int>, int> balance;  // (min, max) -> uses min->max minus max->min
  for (const auto* list : {&triangles.kept, &triangles.flat}) {
    for (const std::array<int, 3>& t : *list) {
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        balance[std::minmax(a, b)] += a < b ? 1 : -1;
      }
    }
  }
  return std::all_of(balance.begin(), balance.end(),
                     [](const auto& edge) { return edge.second == 0; });
}

class MeshSurface final : public SurfaceQuery {
 public:
  MeshSurface(const MeshSurface&) = delete;  // the tree points into m_triangles
  MeshSurface& operator=(const MeshSurface&) = delete;
  MeshSurface(const IndexedMesh& mesh, const std::vector<std::array<int, 3>>& triangles,
              bool closed) {
    for (const std::array<int, 3>& t : triangles) {
      for (int v : t) m_corners.push_back(mesh.vertices[v]);
      m_triangles.emplace_back(to_point(mesh.vertices[t[0]]), to_point(mesh.vertices[t[1]]),
                               to_point(mesh.vertices[t[2]]));
    }
    if (closed) m_winding.emplace(m_corners);
    m_tree.insert(m_triangles.begin(), m_triangles.end());
    m_tree.accelerate_distance_queries();
  }

  SurfaceDistance distance(const Eigen::Vector3d& x_m) const override {
    const auto [closest, triangle] = m_tree.closest_point_and_primitive(to_point(x_m));
    const Eigen::Vector3d offset = x_m - to_eigen(closest);
    const double gap_m = offset.norm();
    if (!(gap_m > 1e-12)) {
      const Eigen::Vector3d a = to_eigen(triangle->vertex(0));
      const Eigen::Vector3d face_normal =
          (to_eigen(triangle->vertex(1)) - a).cross(to_eigen(triangle->vertex(2)) - a).normalized();
      return {0.0, face_normal};
    }
    const Eigen::Vector3d away = offset / gap_m;
    if (m_winding && m_winding->winding_number(x_m) > 0.5) return {-gap_m, -away};  // inside
    return {gap_m, away};
  }

  const std::vector<Eigen::Vector3d>& triangle_corners() const override { return m_corners; }

 private:
  Triangles m_triangles;  // the tree points into it: filled before the tree, never changed
  std::vector<Eigen::Vector3d> m_corners;
  std::optional<WindingNumberTree> m_winding;  // closed meshes only
  Tree m_tree;
};

}  // namespace

std::shared_ptr<const SurfaceQuery> make_mesh_surface(const IndexedMesh& mesh,
                                                      ObstacleMeshReport* report) {
  ObstacleMeshReport local;
  ObstacleMeshReport& r = report ? *report : local;
  r = {};
  const ObstacleTriangles triangles = obstacle_triangles(mesh, r);
  r.closed = is_closed(triangles);
  return std::make_shared<MeshSurface>(mesh, triangles.kept, r.closed);
}

}  // namespace tissu
