#include "topology/corner_uvs.hpp"

#include "topology/complex_navigation.hpp"

namespace tissu {

bool has_corner_uvs(const ClothComplex& lcc) {
  return lcc.darts().begin() != lcc.darts().end() && lcc.info(lcc.darts().begin()).uv.given;
}

Eigen::Vector2d corner_uv(const ClothComplex& lcc, Dart_const_handle dart) {
  const CornerUv& uv = lcc.info(dart).uv;
  return {uv.u, uv.v};
}

bool is_uv_seam(const ClothComplex& lcc, Dart_const_handle dart) {
  if (lcc.is_free<2>(dart)) return false;
  const auto differ = [&](Dart_const_handle p, Dart_const_handle q) {
    const CornerUv& a = lcc.info(p).uv;
    const CornerUv& b = lcc.info(q).uv;
    return a.given != b.given || a.u != b.u || a.v != b.v;
  };
  // the dart a -> b and, across, b -> a: a's corners are the dart and the one after its twin
  const Dart_const_handle twin = lcc.opposite<2>(dart);
  return differ(dart, lcc.next(twin)) || differ(lcc.next(dart), twin);
}

// both read the cloth's having UVs off the darts they copy from, which are old ones: a new dart
// may take any slot of CGAL's container, the first one too, so has_corner_uvs cannot tell here

void interpolate_uvs_at_inserted_vertex(ClothComplex& lcc, Vertex_handle vertex) {
  for (Dart_handle d : darts_leaving(lcc, vertex)) {
    const CornerUv& a = lcc.info(lcc.previous(d)).uv;
    const CornerUv& b = lcc.info(lcc.next(d)).uv;
    lcc.info(d).uv = {0.5 * (a.u + b.u), 0.5 * (a.v + b.v), a.given && b.given};
  }
}

void copy_uvs_to_inserted_edge(ClothComplex& lcc, Dart_handle new_edge) {
  const Dart_handle twin = lcc.opposite<2>(new_edge);
  lcc.info(new_edge).uv = lcc.info(lcc.next(twin)).uv;
  lcc.info(twin).uv = lcc.info(lcc.next(new_edge)).uv;
}

}  // namespace tissu
