#include "topology/flip_edge.hpp"

#include <cassert>
#include <stdexcept>

#include "topology/complex_navigation.hpp"
#include "topology/corner_uvs.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/local_update.hpp"
#include "topology/retriangulation.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

Eigen::Vector3d rest_of(const ClothComplex& lcc, Dart_const_handle d) {
  return to_eigen(lcc.vertex_attribute(d)->info().rest_position);
}

}  // namespace

std::optional<std::string> flip_refusal(const ClothComplex& lcc, Dart_const_handle dart) {
  if (lcc.is_free<2>(dart)) return "the edge is on the border";
  const Dart_const_handle across = lcc.opposite<2>(dart);
  if (!edge_between_triangles(lcc, dart)) return "a face beside it is no triangle";
  // dart a -> b, then b -> c; across b -> a, then a -> e
  const Dart_const_handle b_to_c = lcc.next(dart);
  const Dart_const_handle a_to_e = lcc.next(across);
  const Vertex_const_handle c = lcc.vertex_attribute(lcc.next(b_to_c));
  const Vertex_const_handle e = lcc.vertex_attribute(lcc.next(a_to_e));
  if (c == e || joined_by_edge(lcc, c, e)) return "its far corners are already joined";
  if (is_uv_seam(lcc, dart)) return "it is a UV seam";
  const Eigen::Vector3d a = rest_of(lcc, dart), b = rest_of(lcc, b_to_c);
  const Eigen::Vector3d rc = to_eigen(c->info().rest_position);
  const Eigen::Vector3d re = to_eigen(e->info().rest_position);
  if (!keeps_rest_region({{a, b, rc}, {b, a, re}}, {{rc, a, re}, {re, b, rc}})) {
    return "its quad is not planar and convex in material coordinates";
  }
  return std::nullopt;
}

Dart_handle flip_edge(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings) {
  if (const auto refusal = flip_refusal(lcc, dart)) {
    throw std::invalid_argument("flip_edge: " + *refusal);
  }
  const std::vector<Vertex_handle> corners{
      lcc.vertex_attribute(dart), lcc.vertex_attribute(lcc.next(dart)),
      lcc.vertex_attribute(lcc.previous(dart)),
      lcc.vertex_attribute(lcc.previous(lcc.opposite<2>(dart)))};
  const Eigen::Vector3d momentum_before = free_momentum(corners);
  const FaceRest own = lcc.info<2>(dart);
  const FaceRest across = lcc.info<2>(lcc.opposite<2>(dart));
  // the quad left by the removal runs b -> c -> a -> e -> b
  const Dart_handle c_to_a = lcc.next(lcc.next(dart));
  const Dart_handle e_to_b = lcc.next(lcc.next(lcc.opposite<2>(dart)));
  lcc.remove_cell<1>(dart);
  const Dart_handle c_to_e = lcc.insert_cell_1_in_cell_2(c_to_a, e_to_b);
  lcc.set_attribute<1>(c_to_e, lcc.create_attribute<1>());  // CGAL gives a new edge none
  copy_uvs_to_inserted_edge(lcc, c_to_e);                   // nor its darts UVs
  const std::vector<Dart_handle> faces{c_to_e, lcc.opposite<2>(c_to_e)};
  for (Dart_handle face : faces) {
    FaceRest& rest = lcc.info<2>(face);
    rest.input_area = 0.5 * (own.input_area + across.input_area);
    rest.sizing_per_m2 = 0.5 * (own.sizing_per_m2 + across.sizing_per_m2);
    rest.sizing_metric_per_m2 = 0.5 * (own.sizing_metric_per_m2 + across.sizing_metric_per_m2);
  }
  update_around_faces(lcc, faces, settings);
  // the four corners' masses moved between them: one common velocity change keeps their momentum
  set_free_momentum(corners, momentum_before);
  assert(is_valid_cloth(lcc));
  return lcc.vertex_attribute(c_to_e) == lcc.vertex_attribute(c_to_a) ? c_to_e
                                                                      : lcc.opposite<2>(c_to_e);
}

}  // namespace tissu
