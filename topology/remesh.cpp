#include "topology/remesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "topology/collapse_vertex.hpp"
#include "topology/complex_navigation.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/flip_edge.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/sizing_metric.hpp"
#include "topology/split_edge.hpp"

namespace tissu {
namespace {

/// The margin on the anisotropic Delaunay test: ten times ARCSim's (magic.edge_flip_threshold,
/// 0.01). With ARCSim's, the drape and the flag flipped about 8 edges at almost every pass; with
/// 0.1 the drape came 2.61 % from its fine twin instead of 3.01 %, and the curtain at curvature
/// 1.5 as near with 692 particles instead of 814 (docs/benchmarks.md, "anisotropic remeshing").
constexpr double flip_margin = 0.1;
/// Rounds of flips over the whole cloth at most, in case a round keeps finding some.
constexpr int max_flip_rounds = 8;
/// The most a flip or a collapse may turn a face of the current shape: ARCSim 0.3 flips no edge
/// whose faces meet at 40 degrees or more, so that remeshing does not change the shape of a fold.
const double cos_largest_turn = std::cos(40.0 * 3.14159265358979323846 / 180.0);

/// The strain |l / l0 - 1| of a spring between `a` and `b`, from their current and rest distances.
double pair_strain(Vertex_const_handle a, Vertex_const_handle b) {
  const double rest_m = rest_distance_m(a->info().rest_position, b->info().rest_position);
  return std::abs(std::sqrt(CGAL::squared_distance(a->point(), b->point())) / rest_m - 1.0);
}

/// Whether the current triangles (a, b, c) and (a2, b2, c2) face within the largest turn.
bool within_turn(const Point3& a, const Point3& b, const Point3& c, const Point3& a2,
                 const Point3& b2, const Point3& c2) {
  const Vector3 n = CGAL::cross_product(b - a, c - a);
  const Vector3 n2 = CGAL::cross_product(b2 - a2, c2 - a2);
  return n * n2 > cos_largest_turn * std::sqrt(n.squared_length() * n2.squared_length());
}

/// ARCSim's vertex sizing: the rest-area-weighted mean of the metrics of the faces around `v`.
Eigen::Matrix3d vertex_metric(const ClothComplex& lcc, Vertex_const_handle v) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  double area_m2 = 0.0;
  for (Dart_const_handle d : darts_leaving(lcc, v)) {
    const FaceRest& face = lcc.info<2>(d);
    sum += face.rest_area * face.sizing_metric_per_m2;
    area_m2 += face.rest_area;
  }
  return area_m2 > 0.0 ? Eigen::Matrix3d(sum / area_m2) : sum;
}

/// Every particle's vertex_metric(), taken once at the start of a pass and kept through its
/// edits, as ARCSim keeps its vertex sizing: a particle a split makes takes the mean of the
/// edge's ends.
class VertexMetrics {
 public:
  explicit VertexMetrics(const ClothComplex& lcc) {
    metric_.reserve(lcc.vertex_attributes().size());
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      metric_[&*v] = vertex_metric(lcc, v);
    }
  }
  const Eigen::Matrix3d& operator()(Vertex_const_handle v) const { return metric_.at(&*v); }
  void add_midpoint(Vertex_const_handle middle, Vertex_const_handle a, Vertex_const_handle b) {
    metric_[&*middle] = 0.5 * ((*this)(a) + (*this)(b));
  }

 private:
  std::unordered_map<const void*, Eigen::Matrix3d> metric_;
};

/// The mean of e^T M e over the metrics M of the edge's two ends (ARCSim's edge_metric).
template <class MetricOf>
double pair_metric_length2(const MetricOf& metric_of, Vertex_const_handle a,
                           Vertex_const_handle b) {
  const Point3& ra = a->info().rest_position;
  const Point3& rb = b->info().rest_position;
  return 0.5 * (metric_length2(metric_of(a), ra, rb) + metric_length2(metric_of(b), ra, rb));
}

Eigen::Vector3d rest_of(Vertex_const_handle v) {
  return to_eigen(v->info().rest_position);
}

/// One dart per edge of the faces around `v`.
std::vector<Dart_handle> edges_around(ClothComplex& lcc, Vertex_handle v) {
  std::vector<Dart_handle> edges;
  std::set<Dart_const_handle> seen;
  for (Dart_handle out : darts_leaving(lcc, v)) {
    for (auto d = lcc.darts_of_orbit<1>(out).begin(); d != lcc.darts_of_orbit<1>(out).end(); ++d) {
      if (seen.insert(edge_key(lcc, d)).second) edges.push_back(d);
    }
  }
  return edges;
}

/// Whether flipping the edge of `dart`, (a, b) between (a, b, c) and (b, a, e), leaves the current
/// shape as it is: both pairs of faces, (a, b, c) and (b, a, e) now and (c, a, e) and (e, b, c)
/// after, meet within the largest turn, and the new spring (c, e) is no more strained than the
/// five it joins.
bool flip_keeps_shape(const ClothComplex& lcc, Dart_const_handle dart) {
  const Vertex_const_handle a = lcc.vertex_attribute(dart);
  const Vertex_const_handle b = lcc.vertex_attribute(lcc.next(dart));
  const Vertex_const_handle c = vertex_after_edge(lcc, dart);
  const Vertex_const_handle e = vertex_after_edge(lcc, lcc.opposite<2>(dart));
  const Point3 &pa = a->point(), &pb = b->point(), &pc = c->point(), &pe = e->point();
  if (!within_turn(pa, pb, pc, pb, pa, pe) || !within_turn(pc, pa, pe, pe, pb, pc)) return false;
  const double strain_before = std::max({pair_strain(a, b), pair_strain(b, c), pair_strain(c, a),
                                         pair_strain(a, e), pair_strain(e, b)});
  return pair_strain(c, e) <= strain_before;
}

/// should_flip() with the vertex metrics `metric_of` gives.
template <class MetricOf>
bool should_flip_in(const ClothComplex& lcc, Dart_const_handle dart, const MetricOf& metric_of) {
  if (lcc.is_free<2>(dart)) return false;
  const Vertex_const_handle va = lcc.vertex_attribute(dart);
  const Vertex_const_handle vb = lcc.vertex_attribute(lcc.next(dart));
  const Vertex_const_handle vc = vertex_after_edge(lcc, dart);
  const Vertex_const_handle ve = vertex_after_edge(lcc, lcc.opposite<2>(dart));
  const Eigen::Vector3d a = rest_of(va), b = rest_of(vb), c = rest_of(vc), e = rest_of(ve);
  Eigen::Matrix3d m = 0.25 * (metric_of(va) + metric_of(vb) + metric_of(vc) + metric_of(ve));
  // where the metric asks nothing of the edge (it is under a third of its target in every
  // direction), the Euclidean Delaunay test at the edge's scale: flat cloth keeps well-shaped
  // triangles, which lets collapses go on
  const double scale_per_m2 = 1.0 / (b - a).squaredNorm();
  if (m.trace() < scale_per_m2 / 9.0) m = scale_per_m2 * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
  const auto wedge = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
    return p.cross(q).dot(normal);
  };
  const double at_e = wedge(b - e, a - e);
  const double at_c = wedge(a - c, b - c);
  const double lhs = at_e * (a - c).dot(m * (b - c)) + (b - e).dot(m * (a - e)) * at_c;
  return lhs < -flip_margin * (at_e + at_c);
}

/// Flips the edges of `edges` that should_flip() wants and flip_refusal() allows; returns how many.
/// An edge an earlier flip of the list removed is skipped: its dart no longer runs between the
/// same two particles.
int flip_where_wanted(ClothComplex& lcc, const std::vector<Dart_handle>& edges,
                      const VertexMetrics& metrics, const SpringSettings& settings) {
  std::vector<std::pair<Vertex_const_handle, Vertex_const_handle>> ends;
  for (Dart_handle d : edges)
    ends.emplace_back(lcc.vertex_attribute(d), lcc.vertex_attribute(lcc.next(d)));
  int flips = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Dart_handle d = edges[i];
    if (!lcc.is_dart_used(d) || lcc.vertex_attribute(d) != ends[i].first ||
        lcc.vertex_attribute(lcc.next(d)) != ends[i].second) {
      continue;
    }
    if (should_flip_in(lcc, d, metrics) && !flip_refusal(lcc, d) && flip_keeps_shape(lcc, d)) {
      flip_edge(lcc, d, settings);
      ++flips;
    }
  }
  return flips;
}

std::vector<Dart_handle> all_edges(ClothComplex& lcc) {
  std::vector<Dart_handle> edges;
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    edges.push_back(d);
  }
  return edges;
}

/// Whether splitting the edge of `dart` at its rest midpoint m makes no edge (m, apex) shorter
/// than the shortest edge allowed and no triangle of quality under `min_quality`: a split of a
/// long edge across a thin triangle would join m to an apex that is nearly on the edge.
bool split_keeps_quality(const ClothComplex& lcc, Dart_const_handle dart, double min_edge_m,
                         double min_quality) {
  const Eigen::Vector3d a = rest_of(lcc.vertex_attribute(dart));
  const Eigen::Vector3d b = rest_of(lcc.vertex_attribute(lcc.next(dart)));
  const Eigen::Vector3d m = 0.5 * (a + b);
  std::vector<RestTriangle> halves;
  std::vector<Dart_const_handle> sides{dart};
  if (!lcc.is_free<2>(dart)) sides.push_back(lcc.opposite<2>(dart));
  for (Dart_const_handle side : sides) {
    const Eigen::Vector3d apex = rest_of(vertex_after_edge(lcc, side));
    if ((apex - m).norm() < min_edge_m) return false;
    halves.push_back({a, m, apex});
    halves.push_back({m, b, apex});
  }
  return lowest_quality(halves) >= min_quality;
}

/// Splits every edge longer than 1 in the metric (and at least twice the shortest edge allowed),
/// the longest first, flipping around each new particle; returns the splits and flips made.
std::pair<int, int> split_long_edges(ClothComplex& lcc, const RefinementOptions& o,
                                     VertexMetrics& metrics, const SpringSettings& settings) {
  struct LongEdge {
    double length2;
    Dart_handle dart;
    Vertex_const_handle from, to;
  };
  std::vector<LongEdge> long_edges;
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    if (edge_rest_length_m(lcc, d) < 2.0 * o.min_edge_length_m || !edge_between_triangles(lcc, d)) {
      continue;
    }
    const double length2 =
        pair_metric_length2(metrics, lcc.vertex_attribute(d), lcc.vertex_attribute(lcc.next(d)));
    if (length2 > 1.0) {
      long_edges.push_back(
          {length2, d, lcc.vertex_attribute(d), lcc.vertex_attribute(lcc.next(d))});
    }
  }
  std::stable_sort(long_edges.begin(), long_edges.end(),
                   [](const LongEdge& a, const LongEdge& b) { return a.length2 > b.length2; });
  int splits = 0, flips = 0;
  for (const LongEdge& edge : long_edges) {
    if (lcc.vertex_attributes().size() >= static_cast<std::size_t>(o.max_particles)) break;
    // an earlier split or flip took this edge away
    if (!lcc.is_dart_used(edge.dart) || lcc.vertex_attribute(edge.dart) != edge.from ||
        lcc.vertex_attribute(lcc.next(edge.dart)) != edge.to ||
        !edge_between_triangles(lcc, edge.dart)) {
      continue;
    }
    if (!split_keeps_quality(lcc, edge.dart, o.min_edge_length_m, 0.5 / o.max_aspect_ratio)) {
      continue;
    }
    const Dart_handle from_middle = split_edge(lcc, edge.dart, settings);
    metrics.add_midpoint(lcc.vertex_attribute(from_middle), edge.from, edge.to);
    ++splits;
    flips += flip_where_wanted(lcc, edges_around(lcc, lcc.vertex_attribute(from_middle)), metrics,
                               settings);
  }
  return {splits, flips};
}

/// The neighbours of `v`: the far end of each dart leaving it, and on the border the origin of the
/// dart before the border one.
std::vector<Vertex_handle> neighbours_of(ClothComplex& lcc, Vertex_handle v) {
  std::vector<Vertex_handle> out;
  for (Dart_handle d : darts_leaving(lcc, v)) {
    out.push_back(lcc.vertex_attribute(lcc.next(d)));
    if (lcc.is_free<2>(lcc.previous(d))) out.push_back(lcc.vertex_attribute(lcc.previous(d)));
  }
  return out;
}

/// Whether collapsing `v` onto `u` leaves the current shape as it is: each new triangle
/// (u, w, w') faces within the largest turn of the triangle (v, w, w') it replaces, and no spring
/// at `u` afterwards is more strained than the most strained one around `v` now.
bool collapse_keeps_shape(ClothComplex& lcc, Vertex_handle v, Vertex_handle u) {
  double strain_before = 0.0;
  for (Dart_handle d : darts_leaving(lcc, v)) {
    const Vertex_handle w = lcc.vertex_attribute(lcc.next(d));
    const Vertex_handle w_next = lcc.vertex_attribute(lcc.previous(d));
    strain_before = std::max(
        {strain_before, pair_strain(v, w), pair_strain(v, w_next), pair_strain(w, w_next)});
    if (w == u || w_next == u) continue;
    if (!within_turn(v->point(), w->point(), w_next->point(), u->point(), w->point(),
                     w_next->point())) {
      return false;
    }
  }
  for (Vertex_handle w : neighbours_of(lcc, v)) {
    if (w != u && pair_strain(u, w) > strain_before) return false;
  }
  return true;
}

/// The neighbour of `v` it may collapse onto with the shortest new edges under `hysteresis`, if
/// any (remesh(), step 3).
std::optional<Vertex_handle> collapse_target(ClothComplex& lcc, Vertex_handle v, double hysteresis,
                                             double min_quality, const VertexMetrics& metrics) {
  std::optional<Vertex_handle> best;
  double best_length2 = hysteresis * hysteresis;
  const std::vector<Vertex_handle> neighbours = neighbours_of(lcc, v);
  for (Vertex_handle u : neighbours) {
    // every edge at u afterwards, as the next pass will measure them
    double longest2 = 0.0;
    for (Vertex_handle w : neighbours) {
      if (w != u) longest2 = std::max(longest2, pair_metric_length2(metrics, u, w));
    }
    if (!(longest2 < best_length2)) continue;
    const std::vector<RestTriangle> after = triangles_after_collapse(lcc, v, u);
    if (after.empty() || lowest_quality(after) < min_quality || !collapse_keeps_shape(lcc, v, u)) {
      continue;
    }
    best_length2 = longest2;
    best = u;
  }
  return best;
}

std::pair<int, int> collapse_calm_particles(ClothComplex& lcc, const RefinementOptions& o,
                                            double hysteresis, const VertexMetrics& metrics,
                                            const SpringSettings& settings) {
  std::vector<Vertex_handle> created;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (v->info().source_index < 0 && !v->info().on_crack && !v->info().pinned)
      created.push_back(v);
  }
  std::stable_sort(created.begin(), created.end(), [](Vertex_handle a, Vertex_handle b) {
    return a->info().level > b->info().level;
  });
  int collapses = 0, flips = 0;
  for (Vertex_handle v : created) {
    const std::optional<Vertex_handle> onto =
        collapse_target(lcc, v, hysteresis, 1.0 / o.max_aspect_ratio, metrics);
    int& calm_passes = v->info().calm_passes;
    if (!onto) {
      calm_passes = 0;
      continue;
    }
    if (++calm_passes < o.coarsen_after_passes) continue;
    collapse_vertex(lcc, v, *onto, settings);
    ++collapses;
    flips += flip_where_wanted(lcc, edges_around(lcc, *onto), metrics, settings);
  }
  return {collapses, flips};
}

}  // namespace

double edge_metric_length2(const ClothComplex& lcc, Dart_const_handle dart) {
  return pair_metric_length2([&](Vertex_const_handle v) { return vertex_metric(lcc, v); },
                             lcc.vertex_attribute(dart), lcc.vertex_attribute(lcc.next(dart)));
}

bool should_flip(const ClothComplex& lcc, Dart_const_handle dart) {
  return should_flip_in(lcc, dart, [&](Vertex_const_handle v) { return vertex_metric(lcc, v); });
}

RemeshReport remesh(ClothComplex& lcc, const RefinementOptions& options, double hysteresis,
                    const SpringSettings& settings, const SizingInputs& inputs) {
  compute_sizing_metric(lcc, options, inputs);
  VertexMetrics metrics(lcc);
  RemeshReport report;
  std::tie(report.splits, report.flips) = split_long_edges(lcc, options, metrics, settings);
  for (int round = 0; round < max_flip_rounds; ++round) {
    const int flips = flip_where_wanted(lcc, all_edges(lcc), metrics, settings);
    report.flips += flips;
    if (flips == 0) break;
  }
  if (hysteresis > 0.0) {
    const auto [collapses, flips] =
        collapse_calm_particles(lcc, options, hysteresis, metrics, settings);
    report.collapses = collapses;
    report.flips += flips;
  }
  return report;
}

}  // namespace tissu
