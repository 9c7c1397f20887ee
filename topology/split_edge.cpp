#include "topology/split_edge.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "topology/complex_navigation.hpp"
#include "topology/corner_uvs.hpp"
#include "topology/local_update.hpp"
#include "topology/validity.hpp"

namespace tissu {
Dart_handle split_edge(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings) {
  const bool interior = !lcc.is_free<2>(dart);
  if (!edge_between_triangles(lcc, dart)) {
    throw std::invalid_argument("split_edge: refinement needs triangles on both sides of the edge");
  }
  const Vertex_handle a = lcc.vertex_attribute(dart);
  const Vertex_handle b = lcc.vertex_attribute(lcc.next(dart));
  const Particle& pa = a->info();
  const Particle& pb = b->info();
  Particle middle;
  middle.level =
      1 + std::max({pa.level, pb.level, vertex_after_edge(lcc, dart)->info().level,
                    interior ? vertex_after_edge(lcc, lcc.opposite<2>(dart))->info().level : 0});
  middle.velocity = 0.5 * (pa.velocity + pb.velocity);
  middle.rest_position = CGAL::midpoint(pa.rest_position, pb.rest_position);
  middle.split_edge_end = pa.rest_position;
  // an edge held at both ends (a clamp) stays held along its length
  middle.pinned = pa.pinned && pb.pinned;
  // on one handle's edge it belongs to that handle; between two handles' particles, to the first
  // one's (lib/pin_handles.hpp)
  middle.pin_group = pa.pin_group == pb.pin_group || middle.pinned ? pa.pin_group : -1;

  // dart: a -> m afterwards, next(dart): m -> b; across, opposite<2>(dart): m -> a
  const Vertex_handle m =
      lcc.create_vertex_attribute(CGAL::midpoint(a->point(), b->point()), middle);
  lcc.insert_cell_0_in_cell_1(dart, m);
  interpolate_uvs_at_inserted_vertex(lcc, m);  // CGAL gives the darts from m none

  // cutting a quad returns the new edge's dart on the side of its first dart: both halves are the
  // faces of that dart and of its twin
  std::vector<Dart_handle> faces;
  auto cut = [&](Dart_handle from, Dart_handle to) {
    const Dart_handle new_edge = lcc.insert_cell_1_in_cell_2(from, to);
    lcc.set_attribute<1>(new_edge, lcc.create_attribute<1>());  // CGAL gives a new edge none
    copy_uvs_to_inserted_edge(lcc, new_edge);                   // nor its darts UVs
    faces.push_back(new_edge);
    faces.push_back(lcc.opposite<2>(new_edge));
  };
  // this side is now the quad a m b c: cut it from m to c
  const Dart_handle from_m = lcc.next(dart);
  cut(from_m, lcc.next(lcc.next(from_m)));
  if (interior) {
    // the other side is the quad m a e b: cut it from m to e
    const Dart_handle across_from_m = lcc.opposite<2>(dart);
    cut(across_from_m, lcc.next(lcc.next(across_from_m)));
  }
  update_around_faces(lcc, faces, settings);
  assert(is_valid_cloth(lcc));
  return from_m;
}

}  // namespace tissu
