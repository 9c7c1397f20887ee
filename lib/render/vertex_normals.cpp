#include "lib/render/vertex_normals.hpp"

#include <Eigen/Geometry>
#include <cstddef>

namespace tissu {

Eigen::Vector3d face_vector_area(const IndexedMesh& mesh, const std::vector<int>& face) {
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  const std::size_t n = face.size();
  // about the first vertex, so the result does not depend on where the origin is
  const Eigen::Vector3d& origin = mesh.vertices[face[0]];
  for (std::size_t i = 1; i + 1 < n; ++i)
    area += (mesh.vertices[face[i]] - origin).cross(mesh.vertices[face[i + 1]] - origin);
  return 0.5 * area;
}

std::vector<Eigen::Vector3f> vertex_normals(const IndexedMesh& mesh) {
  std::vector<Eigen::Vector3d> sums(mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (const std::vector<int>& face : mesh.faces) {
    const Eigen::Vector3d area = face_vector_area(mesh, face);
    for (int v : face) sums[v] += area;
  }
  std::vector<Eigen::Vector3f> normals(sums.size(), Eigen::Vector3f::Zero());
  for (std::size_t v = 0; v < sums.size(); ++v) {
    const double length = sums[v].norm();
    if (length > 0.0) normals[v] = (sums[v] / length).cast<float>();
  }
  return normals;
}

}  // namespace tissu
