#include "topology/local_update.hpp"

#include <set>

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

}  // namespace tissu
