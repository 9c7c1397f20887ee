#include "topology/complex_navigation.hpp"

#include "topology/eigen_conversions.hpp"

namespace tissu {

std::vector<Dart_handle> darts_leaving(ClothComplex& lcc, Vertex_handle vertex) {
  std::vector<Dart_handle> out;
  for (auto d = lcc.darts_of_cell<0>(vertex->dart()).begin();
       d != lcc.darts_of_cell<0>(vertex->dart()).end(); ++d) {
    if (lcc.vertex_attribute(d) == vertex) out.push_back(d);
  }
  return out;
}

Vertex_handle vertex_after_edge(ClothComplex& lcc, Dart_handle dart) {
  return lcc.vertex_attribute(lcc.next(lcc.next(dart)));
}

Vertex_handle nearest_vertex(ClothComplex& lcc, const Eigen::Vector3d& rest_point_m) {
  const auto distance2 = [&](Vertex_handle v) {
    return (to_eigen(v->info().rest_position) - rest_point_m).squaredNorm();
  };
  Vertex_handle nearest = lcc.vertex_attributes().begin();
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (distance2(v) < distance2(nearest)) nearest = v;
  }
  return nearest;
}

}  // namespace tissu
