#include "topology/local_update.hpp"

#include <set>

#include "topology/eigen_conversions.hpp"
#include "topology/mass_lumping.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/spring_assignment.hpp"

namespace tissu {

void update_around_faces(ClothComplex& lcc, const std::vector<Dart_handle>& faces,
                         const SpringSettings& settings) {
  std::set<Vertex_handle> vertices;
  std::vector<Dart_handle> darts;
  for (Dart_handle face : faces) {
    lcc.info<2>(face).rest_area = face_rest_area(lcc, face);
    for (auto d = lcc.darts_of_orbit<1>(face).begin(); d != lcc.darts_of_orbit<1>(face).end();
         ++d) {
      vertices.insert(lcc.vertex_attribute(d));
      darts.push_back(d);
      if (!lcc.is_free<2>(d)) darts.push_back(lcc.opposite<2>(d));
    }
  }
  for (Vertex_handle v : vertices) lump_vertex_mass(lcc, v);
  for (Dart_handle d : darts) assign_dart_springs(lcc, d, settings);
}

void repoint_edge_attributes(ClothComplex& lcc, Dart_handle face) {
  for (auto d = lcc.darts_of_orbit<1>(face).begin(); d != lcc.darts_of_orbit<1>(face).end(); ++d) {
    lcc.set_dart_of_attribute<1>(lcc.attribute<1>(d), d);
  }
}

Eigen::Vector3d free_momentum(const std::vector<Vertex_handle>& vertices) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (Vertex_handle v : vertices) {
    if (!v->info().pinned) p += v->info().mass * to_eigen(v->info().velocity);
  }
  return p;
}

void set_free_momentum(const std::vector<Vertex_handle>& vertices,
                       const Eigen::Vector3d& momentum_kg_m_per_s) {
  double free_mass_kg = 0.0;
  for (Vertex_handle v : vertices) free_mass_kg += v->info().pinned ? 0.0 : v->info().mass;
  if (!(free_mass_kg > 0.0)) return;
  const Eigen::Vector3d dv = (momentum_kg_m_per_s - free_momentum(vertices)) / free_mass_kg;
  for (Vertex_handle v : vertices) {
    if (!v->info().pinned) v->info().velocity = v->info().velocity + to_vector(dv);
  }
}

}  // namespace tissu
