#include "topology/mesh_obstacle.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <Eigen/Geometry>
#include <map>
#include <utility>
#include <vector>

#include "topology/eigen_conversions.hpp"

namespace tissu {
namespace {

using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

/// Whether every edge of the triangles is shared by exactly two of them.
bool is_closed(const IndexedMesh& triangles) {
  std::map<std::pair<int, int>, int> uses;
  for (const std::vector<int>& f : triangles.faces) {
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(f[k], f[(k + 1) % 3])];
  }
  for (const auto& [edge, count] : uses) {
    if (count != 2) return false;
  }
  return true;
}

class MeshSurface final : public SurfaceQuery {
 public:
  MeshSurface(const MeshSurface&) = delete;  // the tree points into m_triangles
  MeshSurface& operator=(const MeshSurface&) = delete;
  explicit MeshSurface(const IndexedMesh& triangles) : m_closed(is_closed(triangles)) {
    for (const std::vector<int>& f : triangles.faces) {
      for (int v : f) m_corners.push_back(triangles.vertices[v]);
      m_triangles.emplace_back(to_point(triangles.vertices[f[0]]),
                               to_point(triangles.vertices[f[1]]),
                               to_point(triangles.vertices[f[2]]));
    }
    m_tree.insert(m_triangles.begin(), m_triangles.end());
    m_tree.accelerate_distance_queries();
  }

  SurfaceDistance distance(const Eigen::Vector3d& x_m) const override {
    const auto [closest, triangle] = m_tree.closest_point_and_primitive(to_point(x_m));
    const Eigen::Vector3d offset = x_m - to_eigen(closest);
    const Eigen::Vector3d a = to_eigen(triangle->vertex(0));
    const Eigen::Vector3d face_normal =
        (to_eigen(triangle->vertex(1)) - a).cross(to_eigen(triangle->vertex(2)) - a).normalized();
    const double gap_m = offset.norm();
    if (!(gap_m > 1e-12)) return {0.0, face_normal};
    const Eigen::Vector3d away = offset / gap_m;
    if (m_closed && away.dot(face_normal) < 0.0) return {-gap_m, -away};  // inside
    return {gap_m, away};
  }

  const std::vector<Eigen::Vector3d>& triangle_corners() const override { return m_corners; }

 private:
  bool m_closed;
  Triangles m_triangles;  // the tree points into it: filled before the tree, never changed
  std::vector<Eigen::Vector3d> m_corners;
  Tree m_tree;
};

}  // namespace

std::shared_ptr<const SurfaceQuery> make_mesh_surface(const IndexedMesh& mesh) {
  validate_indexed_mesh(mesh);
  return std::make_shared<MeshSurface>(triangulate_quads(mesh));
}

}  // namespace tissu
