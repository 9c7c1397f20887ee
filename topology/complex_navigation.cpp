#include "topology/complex_navigation.hpp"

#include "topology/eigen_conversions.hpp"

namespace tissu {

template <MaybeConstClothComplex Complex>
std::vector<Dart_handle_of<Complex>> darts_leaving(Complex& lcc, Vertex_handle_of<Complex> vertex) {
  std::vector<Dart_handle_of<Complex>> out;
  for (auto d = lcc.template darts_of_cell<0>(vertex->dart()).begin();
       d != lcc.template darts_of_cell<0>(vertex->dart()).end(); ++d) {
    if (lcc.vertex_attribute(d) == vertex) out.push_back(d);
  }
  return out;
}

Vertex_const_handle vertex_after_edge(const ClothComplex& lcc, Dart_const_handle dart) {
  return lcc.vertex_attribute(lcc.next(lcc.next(dart)));
}

bool face_is_triangle(const ClothComplex& lcc, Dart_const_handle dart) {
  return lcc.darts_of_orbit<1>(dart).size() == 3;
}

bool edge_between_triangles(const ClothComplex& lcc, Dart_const_handle dart) {
  return face_is_triangle(lcc, dart) &&
         (lcc.is_free<2>(dart) || face_is_triangle(lcc, lcc.opposite<2>(dart)));
}

Dart_const_handle edge_key(const ClothComplex& lcc, Dart_const_handle dart) {
  return lcc.is_free<2>(dart) ? dart : std::min(dart, lcc.opposite<2>(dart));
}

bool joined_by_edge(const ClothComplex& lcc, Vertex_const_handle a, Vertex_const_handle b) {
  // every edge at `a` has a dart leaving `a` or, on the border, arriving before one that does
  for (Dart_const_handle d : darts_leaving(lcc, a)) {
    if (lcc.vertex_attribute(lcc.next(d)) == b || lcc.vertex_attribute(lcc.previous(d)) == b) {
      return true;
    }
  }
  return false;
}

template <MaybeConstClothComplex Complex>
Vertex_handle_of<Complex> nearest_vertex(Complex& lcc, const Eigen::Vector3d& rest_point_m) {
  const auto distance2 = [&](Vertex_const_handle v) {
    return (to_eigen(v->info().rest_position) - rest_point_m).squaredNorm();
  };
  Vertex_handle_of<Complex> nearest = lcc.vertex_attributes().begin();
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (distance2(v) < distance2(nearest)) nearest = v;
  }
  return nearest;
}

template std::vector<Dart_handle> darts_leaving(ClothComplex&, Vertex_handle);
template std::vector<Dart_const_handle> darts_leaving(const ClothComplex&, Vertex_const_handle);
template Vertex_handle nearest_vertex(ClothComplex&, const Eigen::Vector3d&);
template Vertex_const_handle nearest_vertex(const ClothComplex&, const Eigen::Vector3d&);

}  // namespace tissu
