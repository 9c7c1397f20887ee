#include "topology/collapse_vertex.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "topology/complex_navigation.hpp"
#include "topology/corner_uvs.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/local_update.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

/// The triangles around a vertex v, in turn: out[i] runs v -> link[i] in the triangle
/// (v, link[i], link[i + 1]), indices modulo the link's size inside the cloth; on the border the
/// link has one vertex more than there are triangles (link[0] and link.back() on the border).
template <MaybeConstClothComplex Complex>
struct Star {
  std::vector<Dart_handle_of<Complex>> out;
  std::vector<Vertex_handle_of<Complex>> link;
  bool border = false;

  std::size_t faces() const { return out.size(); }
  /// Where `w` is in the link, or the link's size when it is not there.
  std::size_t index_of(Vertex_const_handle w) const {
    return static_cast<std::size_t>(std::find(link.begin(), link.end(), w) - link.begin());
  }
};

/// The star of `v`, if its faces are triangles forming one fan.
template <MaybeConstClothComplex Complex>
std::optional<Star<Complex>> star_of(Complex& lcc, Vertex_handle_of<Complex> v) {
  const auto all = darts_leaving(lcc, v);
  if (all.empty()) return std::nullopt;
  Star<Complex> star;
  auto start = all.front();
  // on the border, start from the border edge whose dart leaves v
  for (auto d : all) {
    if (lcc.template is_free<2>(d)) {
      if (star.border) return std::nullopt;  // two border fans: a vertex torn through
      star.border = true;
      start = d;
    }
  }
  for (auto d = start; star.out.size() <= all.size();) {
    if (!face_is_triangle(lcc, d)) return std::nullopt;
    star.out.push_back(d);
    star.link.push_back(lcc.vertex_attribute(lcc.next(d)));
    const auto back_to_v = lcc.previous(d);
    if (lcc.template is_free<2>(back_to_v)) {
      star.link.push_back(lcc.vertex_attribute(back_to_v));
      break;
    }
    d = lcc.template opposite<2>(back_to_v);
    if (d == start) break;
  }
  if (star.out.size() != all.size()) return std::nullopt;
  return star;
}

Eigen::Vector3d rest_of(Vertex_const_handle v) {
  return to_eigen(v->info().rest_position);
}

/// The link index of the triangle's second corner for each triangle of `star` not touching the
/// link vertex at `kept`: the triangles (kept, link[i], link[i + 1]) a collapse onto it leaves.
template <class StarType>
std::vector<std::size_t> fan_sides(const StarType& star, std::size_t kept) {
  std::vector<std::size_t> sides;
  for (std::size_t i = 0; i < star.faces(); ++i) {
    const std::size_t j = (i + 1) % star.link.size();
    if (i != kept && j != kept) sides.push_back(i);
  }
  return sides;
}

/// Whether `kept` at link index `at` may take the vertex's place: inside, with four neighbours or
/// more; on the border, as one of the two border neighbours, with two faces or more.
template <class StarType>
bool may_collapse_to(const StarType& star, std::size_t at) {
  if (at >= star.link.size()) return false;
  if (!star.border) return star.link.size() >= 4;
  return star.faces() >= 2 && (at == 0 || at + 1 == star.link.size());
}

/// Whether collapsing onto link index `at` joins `kept` to a vertex it is already joined to
/// elsewhere (the link condition).
bool breaks_link_condition(const ClothComplex& lcc, const Star<const ClothComplex>& star,
                           std::size_t at) {
  const std::size_t k = star.link.size();
  for (std::size_t i = 0; i < k; ++i) {
    const bool neighbour_in_fan = i == at || (star.border ? i + 1 == at || i == at + 1
                                                          : i == (at + 1) % k || (i + 1) % k == at);
    if (!neighbour_in_fan && joined_by_edge(lcc, star.link[at], star.link[i])) return true;
  }
  return false;
}

}  // namespace

std::vector<RestTriangle> triangles_after_collapse(const ClothComplex& lcc,
                                                   Vertex_const_handle removed,
                                                   Vertex_const_handle kept) {
  if (collapse_refusal(lcc, removed, kept)) return {};
  const auto star = *star_of(lcc, removed);
  const std::size_t at = star.index_of(kept);
  std::vector<RestTriangle> after;
  for (std::size_t i : fan_sides(star, at)) {
    after.push_back(
        {rest_of(kept), rest_of(star.link[i]), rest_of(star.link[(i + 1) % star.link.size()])});
  }
  return after;
}

std::optional<std::string> collapse_refusal(const ClothComplex& lcc, Vertex_const_handle removed,
                                            Vertex_const_handle kept) {
  const Particle& p = removed->info();
  if (p.source_index >= 0) return "it is a particle of the input mesh";
  if (p.pinned || p.pin_group >= 0) return "it is pinned, or will be";
  if (p.on_crack) return "it is on a crack";
  const auto star = star_of(lcc, removed);
  if (!star) return "its faces are not one fan of triangles";
  const std::size_t at = star->index_of(kept);
  if (!may_collapse_to(*star, at)) {
    return "it has too few faces, or would leave the border towards the inside";
  }
  if (breaks_link_condition(lcc, *star, at)) return "the kept vertex is already joined elsewhere";
  for (Dart_const_handle d : star->out) {
    if (is_uv_seam(lcc, d)) return "an edge at it is a UV seam";
  }
  std::vector<RestTriangle> before;
  std::vector<RestTriangle> after;
  const std::size_t k = star->link.size();
  for (std::size_t i = 0; i < star->faces(); ++i) {
    before.push_back({rest_of(removed), rest_of(star->link[i]), rest_of(star->link[(i + 1) % k])});
  }
  for (std::size_t i : fan_sides(*star, at)) {
    after.push_back({rest_of(kept), rest_of(star->link[i]), rest_of(star->link[(i + 1) % k])});
  }
  if (!keeps_rest_region(before, after)) {
    return "the new triangles would not tile its faces' rest region";
  }
  return std::nullopt;
}

void collapse_vertex(ClothComplex& lcc, Vertex_handle removed, Vertex_handle kept,
                     const SpringSettings& settings) {
  if (const auto refusal = collapse_refusal(lcc, removed, kept)) {
    throw std::invalid_argument("collapse_vertex: " + *refusal);
  }
  Star<ClothComplex> star = *star_of(lcc, removed);
  std::size_t at = star.index_of(kept);
  if (!star.border) {  // turn the star so that kept is link[0]
    std::rotate(star.out.begin(), star.out.begin() + at, star.out.end());
    std::rotate(star.link.begin(), star.link.begin() + at, star.link.end());
    at = 0;
  }
  // the link's edges (link[i] -> link[i + 1]) all stay; the new faces each hold one
  std::vector<Dart_handle> link_darts;
  for (Dart_handle d : star.out) link_darts.push_back(lcc.next(d));
  double input_area_m4 = 0.0, rest_area_m2 = 0.0, sizing_sum_per_m2 = 0.0;
  Eigen::Matrix3d metric_sum_per_m2 = Eigen::Matrix3d::Zero();
  for (Dart_handle d : star.out) {
    const FaceRest& face = lcc.info<2>(d);
    input_area_m4 += face.input_area * face.rest_area;
    rest_area_m2 += face.rest_area;
    sizing_sum_per_m2 += face.sizing_per_m2;
    metric_sum_per_m2 += face.sizing_metric_per_m2;
  }
  std::vector<Vertex_handle> neighbours = star.link;
  std::vector<Vertex_handle> with_removed = neighbours;
  with_removed.push_back(removed);
  const Eigen::Vector3d momentum_before = free_momentum(with_removed);

  // Leave `removed` with two edges, then remove it, which joins them into one edge (CGAL's
  // remove_cell<0>): inside, the edges to link[0] (kept) and link[2], leaving the triangle
  // (link[0], link[1], link[2]) and the polygon (link[2], ..., link[k - 1], link[0]); on the
  // border, its two border edges, leaving the polygon of the whole link.
  for (std::size_t i = 1; i < star.faces(); ++i) {
    if (!star.border && i == 2) continue;
    lcc.remove_cell<1>(star.out[i]);
  }
  lcc.remove_cell<0>(star.out[0]);
  // a dart leaving kept in the polygon, then cut the polygon into the fan from there
  Dart_handle from_kept = star.border && at == 0 ? link_darts[0] : lcc.next(link_darts.back());
  while (lcc.darts_of_orbit<1>(from_kept).size() > 3) {
    const Dart_handle cut = lcc.insert_cell_1_in_cell_2(from_kept, lcc.next(lcc.next(from_kept)));
    lcc.set_attribute<1>(cut, lcc.create_attribute<1>());  // CGAL gives a new edge none
    copy_uvs_to_inserted_edge(lcc, cut);                   // nor its darts UVs
    // from_kept's face is now the triangle (kept, p1, p2); the rest lies across its closing edge
    from_kept = lcc.opposite<2>(lcc.next(lcc.next(from_kept)));
  }
  std::vector<Dart_handle> faces;
  for (std::size_t i : fan_sides(star, at)) faces.push_back(link_darts[i]);
  for (Dart_handle face : faces) {
    repoint_edge_attributes(lcc, face);  // the edge remove_cell<0> joined
    FaceRest& rest = lcc.info<2>(face);
    rest.input_area = input_area_m4 / rest_area_m2;
    rest.sizing_per_m2 = sizing_sum_per_m2 / static_cast<double>(star.faces());
    rest.sizing_metric_per_m2 = metric_sum_per_m2 / static_cast<double>(star.faces());
  }
  update_around_faces(lcc, faces, settings);
  set_free_momentum(neighbours, momentum_before);
  assert(is_valid_cloth(lcc));
}

}  // namespace tissu
