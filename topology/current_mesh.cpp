#include "topology/current_mesh.hpp"

#include "topology/corner_uvs.hpp"
#include "topology/eigen_conversions.hpp"

namespace tissu {

IndexedMesh current_mesh(const ClothComplex& lcc) {
  IndexedMesh mesh;
  mesh.vertices.resize(lcc.vertex_attributes().size());
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    mesh.vertices.at(v->info().index_at_last_compile) = to_eigen(v->point());
  }
  const bool with_uvs = has_corner_uvs(lcc);
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    std::vector<int>& face = mesh.faces.emplace_back();
    std::vector<Eigen::Vector2d>* uvs = with_uvs ? &mesh.face_uvs.emplace_back() : nullptr;
    for (auto c = lcc.darts_of_orbit<1>(d).begin(); c != lcc.darts_of_orbit<1>(d).end(); ++c) {
      face.push_back(lcc.vertex_attribute(c)->info().index_at_last_compile);
      if (uvs != nullptr) uvs->push_back(corner_uv(lcc, c));
    }
  }
  return mesh;
}

std::vector<Eigen::Vector3d> rest_positions(const ClothComplex& lcc) {
  std::vector<Eigen::Vector3d> rest_m(lcc.vertex_attributes().size());
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    rest_m.at(v->info().index_at_last_compile) = to_eigen(v->info().rest_position);
  }
  return rest_m;
}

}  // namespace tissu
