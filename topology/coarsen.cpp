#include "topology/coarsen.hpp"

#include <algorithm>
#include <cassert>
#include <optional>
#include <vector>

#include "topology/complex_navigation.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/local_update.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/sizing_field.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

/// A vertex inserted by one bisection of the edge (a, b) and joined to one or two corners, with
/// the handles undo() edits through.
struct Bisection {
  Vertex_handle middle;
  std::vector<Dart_handle> cut_edges;  ///< darts from the middle to each corner
  /// a dart of each parent face, not touching the middle
  std::vector<Dart_handle> corner_faces;
  std::vector<Vertex_handle> patch;  ///< the parent faces' vertices, middle excluded
  double parent_edge_m = 0.0;        ///< rest length of the edge (a, b) undoing restores
};

/// Whether (a, b) is the edge whose split made `m`: m is its midpoint and a or b is the end
/// recorded at the split (the two diagonals of a grid cell share their midpoint).
bool is_split_edge_of(Vertex_const_handle m, Vertex_const_handle a, Vertex_const_handle b) {
  const Point3& ra = a->info().rest_position;
  const Point3& rb = b->info().rest_position;
  const double tolerance_m2 = 1e-20 * CGAL::squared_distance(ra, rb);
  const Point3& end = m->info().split_edge_end;
  return CGAL::squared_distance(CGAL::midpoint(ra, rb), m->info().rest_position) <= tolerance_m2 &&
         (CGAL::squared_distance(ra, end) <= tolerance_m2 ||
          CGAL::squared_distance(rb, end) <= tolerance_m2);
}

/// The bisection that created `m`, if its neighbourhood is still exactly that.
std::optional<Bisection> bisection_at(ClothComplex& lcc, Vertex_handle m) {
  const std::vector<Dart_handle> out = darts_leaving(lcc, m);
  // neighbours: the far end of each outgoing dart, plus, on the boundary, the origin of the dart
  // that ends at m without a twin
  std::vector<std::pair<Vertex_handle, Dart_handle>> neighbours;  // with the dart m -> it
  for (Dart_handle d : out) {
    neighbours.emplace_back(lcc.vertex_attribute(lcc.next(d)), d);
    const Dart_handle incoming = lcc.previous(d);
    if (lcc.is_free<2>(incoming)) {
      neighbours.emplace_back(lcc.vertex_attribute(incoming), nullptr);
    }
  }
  const bool interior = neighbours.size() == 4 && out.size() == 4;
  const bool boundary = neighbours.size() == 3 && out.size() == 2;
  if (!interior && !boundary) return std::nullopt;
  for (std::size_t i = 0; i < neighbours.size(); ++i) {
    for (std::size_t j = i + 1; j < neighbours.size(); ++j) {
      if (!is_split_edge_of(m, neighbours[i].first, neighbours[j].first)) continue;
      Bisection b{m, {}, {}, {}, 0.0};
      b.parent_edge_m = rest_distance_m(neighbours[i].first->info().rest_position,
                                        neighbours[j].first->info().rest_position);
      for (std::size_t k = 0; k < neighbours.size(); ++k) {
        b.patch.push_back(neighbours[k].first);
        if (k == i || k == j) continue;
        const Dart_handle to_corner = neighbours[k].second;
        if (to_corner == nullptr || lcc.is_free<2>(to_corner)) return std::nullopt;
        b.cut_edges.push_back(to_corner);
        // in the face of m -> corner, the dart after it leaves the corner away from m
        b.corner_faces.push_back(lcc.next(to_corner));
      }
      return b;
    }
  }
  return std::nullopt;
}

/// Whether the parent edge of `b` would be short enough for every face around its middle: its
/// length in each face's sizing metric below `hysteresis` (so that a restored triangle is not
/// split again at the next pass).
bool calm_around(const ClothComplex& lcc, const Bisection& b, double hysteresis) {
  const double limit = hysteresis * hysteresis / (b.parent_edge_m * b.parent_edge_m);
  for (Dart_const_handle d : darts_leaving(lcc, Vertex_const_handle(b.middle))) {
    if (!(lcc.info<2>(d).sizing_per_m2 < limit)) return false;
  }
  return true;
}

void undo(ClothComplex& lcc, const Bisection& b, const SpringSettings& settings) {
  std::vector<Vertex_handle> with_middle = b.patch;
  with_middle.push_back(b.middle);
  const Eigen::Vector3d momentum_before = free_momentum(with_middle);

  for (Dart_handle cut : b.cut_edges) lcc.remove_cell<1>(cut);
  lcc.remove_cell<0>(darts_leaving(lcc, b.middle).front());
  for (Dart_handle face : b.corner_faces) repoint_edge_attributes(lcc, face);
  update_around_faces(lcc, b.corner_faces, settings);

  // hand the removed particle's momentum to the free corners (a pinned particle's is the clamp's)
  set_free_momentum(b.patch, momentum_before);
}

}  // namespace

CoarseningReport coarsen(ClothComplex& lcc, const RefinementOptions& options, double hysteresis,
                         const SpringSettings& settings, const SizingInputs& inputs) {
  compute_sizing(lcc, options, inputs);
  return coarsen_on_current_sizing(lcc, options, hysteresis, settings);
}

CoarseningReport coarsen_on_current_sizing(ClothComplex& lcc, const RefinementOptions& options,
                                           double hysteresis, const SpringSettings& settings) {
  CoarseningReport report;
  std::vector<Vertex_handle> created;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Particle& p = v->info();
    if (p.source_index < 0 && !p.on_crack) created.push_back(v);
  }
  // highest level first: whatever changed a particle's neighbourhood after its split is undone
  // before it (equal levels were never neighbours when made, so their order does not matter)
  std::stable_sort(created.begin(), created.end(), [](Vertex_handle a, Vertex_handle b) {
    return a->info().level > b->info().level;
  });
  for (Vertex_handle v : created) {
    const std::optional<Bisection> b = bisection_at(lcc, v);
    int& calm_passes = v->info().calm_passes;
    if (!b || !calm_around(lcc, *b, hysteresis) ||
        (options.max_edge_length_m > 0.0 && b->parent_edge_m > options.max_edge_length_m)) {
      calm_passes = 0;
      continue;
    }
    if (++calm_passes < options.coarsen_after_passes) continue;
    undo(lcc, *b, settings);
    ++report.merges;
  }
  assert(is_valid_cloth(lcc));
  return report;
}

}  // namespace tissu
