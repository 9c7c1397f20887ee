#pragma once
// Exact self-intersection of a simulated surface, for tests: CGAL's box intersection and exact
// triangle-triangle test.

#include <CGAL/box_intersection_d.h>

#include <map>
#include <tuple>
#include <vector>

#include "lib/shape_distance.hpp"
#include "topology/eigen_conversions.hpp"

namespace tissu::test {

/// Pairs of faces of `surface` (triangles) that intersect, exactly, among the pairs that share
/// neither a vertex nor a material point: neighbours touch where they share a vertex, and the two
/// lips of a cut or tear where they were one (their particles share material coordinates).
inline int intersecting_face_pairs(const MaterialSurface& surface) {
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::size_t,
                                                          CGAL::Box_intersection_d::ID_EXPLICIT>;
  const IndexedMesh& mesh = surface.current;
  // the material point of each vertex: vertices with equal material coordinates share one
  std::map<std::tuple<double, double, double>, int> material_ids;
  std::vector<int> material_point(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d& r = surface.rest_m.empty() ? mesh.vertices[v] : surface.rest_m[v];
    material_point[v] =
        material_ids.try_emplace({r.x(), r.y(), r.z()}, static_cast<int>(v)).first->second;
  }
  std::vector<Kernel::Triangle_3> triangles;
  std::vector<Box> boxes;
  for (const std::vector<int>& f : mesh.faces) {
    auto point = [&](int v) { return to_point(mesh.vertices[v]); };
    triangles.emplace_back(point(f[0]), point(f[1]), point(f[2]));
    boxes.emplace_back(triangles.back().bbox(), triangles.size() - 1);
  }
  int intersecting = 0;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    for (int u : mesh.faces[a.handle()]) {
      for (int v : mesh.faces[b.handle()]) {
        if (material_point[u] == material_point[v]) return;
      }
    }
    if (CGAL::do_intersect(triangles[a.handle()], triangles[b.handle()])) ++intersecting;
  });
  return intersecting;
}

}  // namespace tissu::test
