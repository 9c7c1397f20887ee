#include "topology/rest_geometry.hpp"

#include <cmath>

namespace tissu {

const Point3& rest_position(const ClothComplex& lcc, Dart_const_handle dart) {
  return lcc.vertex_attribute(dart)->info().rest_position;
}

double rest_distance_m(const Point3& a_m, const Point3& b_m) {
  return std::sqrt(CGAL::squared_distance(a_m, b_m));
}

double edge_rest_length_m(const ClothComplex& lcc, Dart_const_handle dart) {
  return rest_distance_m(rest_position(lcc, dart), rest_position(lcc, lcc.next(dart)));
}

double face_rest_area(const ClothComplex& lcc, Dart_const_handle dart) {
  Vector3 twice_vector_area = CGAL::NULL_VECTOR;
  for (auto d = lcc.darts_of_orbit<1>(dart).begin(); d != lcc.darts_of_orbit<1>(dart).end(); ++d) {
    const Vector3 p = rest_position(lcc, d) - CGAL::ORIGIN;
    const Vector3 q = rest_position(lcc, lcc.next(d)) - CGAL::ORIGIN;
    twice_vector_area = twice_vector_area + CGAL::cross_product(p, q);
  }
  return 0.5 * std::sqrt(twice_vector_area.squared_length());
}

void assign_face_rest(ClothComplex& lcc, double areal_density_kg_per_m2) {
  for (auto face = lcc.attributes<2>().begin(); face != lcc.attributes<2>().end(); ++face) {
    face->info().rest_area = face_rest_area(lcc, face->dart());
    face->info().areal_density = areal_density_kg_per_m2;
    face->info().input_area = face->info().rest_area;
  }
}

}  // namespace tissu
