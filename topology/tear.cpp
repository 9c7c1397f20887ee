#include "topology/tear.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "topology/complex_navigation.hpp"
#include "topology/edge_measures.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/local_update.hpp"
#include "topology/polyline.hpp"
#include "topology/refine.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

Eigen::Vector3d rest_of(Vertex_const_handle v) {
  return to_eigen(v->info().rest_position);
}

void add(TearReport& total, const TearReport& more) {
  total.tears += more.tears;
  total.new_particles += more.new_particles;
  total.tip_refinements += more.tip_refinements;
}

/// Whether the region holds the edge from rest position a to b: its midpoint lies in the box, or
/// it passes within half the width of the line (so the edges crossing a perforation line are
/// weakened at any resolution).
bool holds(const WeakRegion& region, const Eigen::Vector3d& a_m, const Eigen::Vector3d& b_m) {
  if (region.kind == WeakRegion::Kind::box) return region.box.contains(0.5 * (a_m + b_m));
  return polyline_segment_distance(region.points_m, a_m, b_m) <= 0.5 * region.width_m;
}

/// The strain at which the edge from rest position a to b tears (dimensionless).
double tearing_strain_of(const TearingOptions& o, const Eigen::Vector3d& a_m,
                         const Eigen::Vector3d& b_m) {
  double factor = 1.0;
  for (const WeakRegion& region : o.weak_regions) {
    if (holds(region, a_m, b_m)) factor = std::min(factor, region.factor);
  }
  return o.strain_threshold * factor;
}

/// Whether every edge around `v` has a face on both sides.
bool fan_is_closed(const ClothComplex& lcc, Vertex_const_handle v) {
  for (Dart_const_handle d : darts_leaving(lcc, v)) {
    if (lcc.is_free<2>(d) || lcc.is_free<2>(lcc.previous(d))) return false;
  }
  return true;
}

/// Unit direction of largest stretch around `v`, in material coordinates: the top eigenvector of
/// sum_f A_f C_f, where C_f = F^T F is the right Cauchy-Green tensor of the corner triangle of
/// face f at v (its edges leaving v), written in rest space, and A_f that triangle's rest area.
Eigen::Vector3d largest_stretch_direction(const ClothComplex& lcc, Vertex_const_handle v) {
  Eigen::Matrix3d weighted_c = Eigen::Matrix3d::Zero();
  for (Dart_const_handle d : darts_leaving(lcc, v)) {
    const Vertex_const_handle a = lcc.vertex_attribute(lcc.next(d));
    const Vertex_const_handle b = lcc.vertex_attribute(lcc.previous(d));
    const Eigen::Vector3d rest_a = rest_of(a) - rest_of(v), rest_b = rest_of(b) - rest_of(v);
    const Eigen::Vector3d normal = rest_a.cross(rest_b);
    if (!(normal.norm() > 0.0)) continue;
    // orthonormal rest frame (t1, t2) of the triangle; Dm holds its edges in that frame
    const Eigen::Vector3d t1 = rest_a.normalized();
    const Eigen::Vector3d t2 = normal.normalized().cross(t1);
    Eigen::Matrix2d dm;
    dm << rest_a.dot(t1), rest_b.dot(t1), 0.0, rest_b.dot(t2);
    Eigen::Matrix<double, 3, 2> ds;
    ds.col(0) = to_eigen(a->point()) - to_eigen(v->point());
    ds.col(1) = to_eigen(b->point()) - to_eigen(v->point());
    const Eigen::Matrix<double, 3, 2> f = ds * dm.inverse();
    Eigen::Matrix<double, 3, 2> frame;
    frame << t1, t2;
    weighted_c += 0.5 * normal.norm() * frame * (f.transpose() * f) * frame.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(weighted_c);
  return eigen.eigenvectors().col(2);  // eigenvalues ascend
}

/// Whether tearing the dart's edge would cut off a piece of fewer than `min_faces` faces: a
/// search from each side over faces joined by sewn edges (the torn one excluded) that stops at
/// `min_faces` faces or on reaching the other side.
bool sheds_a_fragment(const ClothComplex& lcc, Dart_const_handle d, int min_faces) {
  const Dart_const_handle other = lcc.opposite<2>(d);
  for (Dart_const_handle start : {d, other}) {
    const Face_const_handle goal = lcc.attribute<2>(start == d ? other : d);
    std::set<Face_const_handle> seen{lcc.attribute<2>(start)};
    std::vector<Dart_const_handle> frontier{start};
    bool joined = false;
    while (!frontier.empty() && !joined && static_cast<int>(seen.size()) < min_faces) {
      const Dart_const_handle face = frontier.back();
      frontier.pop_back();
      for (auto e = lcc.darts_of_orbit<1>(face).begin(); e != lcc.darts_of_orbit<1>(face).end();
           ++e) {
        if (lcc.is_free<2>(e) || e == d || e == other) continue;
        const Dart_const_handle across = lcc.opposite<2>(e);
        if (lcc.attribute<2>(across) == goal) joined = true;
        if (seen.insert(lcc.attribute<2>(across)).second) frontier.push_back(across);
      }
    }
    if (!joined && static_cast<int>(seen.size()) < min_faces) return true;
  }
  return false;
}

/// The edges a fracture at `v` tears: the interior edge most perpendicular (in rest space) to the
/// largest stretch, and for a closed fan also the best one on the other side of the stretch line;
/// never one that would cut off a piece of fewer than `min_piece_faces` faces.
std::vector<Dart_handle> crack_edges(ClothComplex& lcc, Vertex_handle v, int min_piece_faces) {
  const Eigen::Vector3d stretch = largest_stretch_direction(lcc, v);
  struct Candidate {
    Dart_handle dart;
    Eigen::Vector3d direction;  ///< rest space, unit
    double alignment;           ///< |cos| of the angle to the stretch
  };
  std::vector<Candidate> candidates;
  for (Dart_handle d : darts_leaving(lcc, v)) {
    if (lcc.is_free<2>(d) || sheds_a_fragment(lcc, d, min_piece_faces)) continue;
    const Eigen::Vector3d u =
        (rest_of(lcc.vertex_attribute(lcc.next(d))) - rest_of(v)).normalized();
    candidates.push_back({d, u, std::abs(u.dot(stretch))});
  }
  auto best_where = [&](auto accept) -> const Candidate* {
    const Candidate* best = nullptr;
    for (const Candidate& c : candidates) {
      if (accept(c) && (best == nullptr || c.alignment < best->alignment)) best = &c;
    }
    return best;
  };
  const Candidate* first = best_where([](const Candidate&) { return true; });
  if (first == nullptr) return {};
  std::vector<Dart_handle> edges{first->dart};
  if (fan_is_closed(lcc, v)) {
    // the side of the stretch line the first edge leaves on
    const Eigen::Vector3d across = first->direction - first->direction.dot(stretch) * stretch;
    const Candidate* second =
        best_where([&](const Candidate& c) { return c.direction.dot(across) < 0.0; });
    if (second != nullptr) edges.push_back(second->dart);
  }
  return edges;
}

/// An edge over its tearing strain, by its two ends: tear() breaks the cloth at one of them.
struct Overstretched {
  double ratio;  ///< strain over tearing strain, > 1
  Vertex_handle a, b;
};

/// The edges over their tearing strain, most overstretched first (container order on ties).
std::vector<Overstretched> overstretched_edges(ClothComplex& lcc, const TearingOptions& options) {
  std::vector<Overstretched> edges;
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    const Vertex_handle a = lcc.vertex_attribute(d);
    const Vertex_handle b = lcc.vertex_attribute(lcc.next(d));
    const double ratio =
        edge_engineering_strain(lcc, d) / tearing_strain_of(options, rest_of(a), rest_of(b));
    if (ratio > 1.0) edges.push_back({ratio, a, b});
  }
  std::stable_sort(edges.begin(), edges.end(), [](const Overstretched& x, const Overstretched& y) {
    return x.ratio > y.ratio;
  });
  return edges;
}

/// The end of an overstretched edge where the cloth breaks: one whose fan is open (on the border
/// or a crack tip, where one torn edge splits it), then one already on a crack, then `a`.
Vertex_handle breaking_end(const ClothComplex& lcc, const Overstretched& edge) {
  const bool a_open = !fan_is_closed(lcc, edge.a);
  const bool b_open = !fan_is_closed(lcc, edge.b);
  if (a_open != b_open) return a_open ? edge.a : edge.b;
  return !edge.a->info().on_crack && edge.b->info().on_crack ? edge.b : edge.a;
}

/// The edges of the knife's walk along the polyline (see cut_along).
std::vector<Dart_handle> cut_path(ClothComplex& lcc, const std::vector<Eigen::Vector3d>& polyline) {
  std::vector<Dart_handle> path;
  Vertex_handle here = nearest_vertex(lcc, polyline.front());
  double along_m = project_on_polyline(polyline, rest_of(here)).arc_length_m;
  std::set<Vertex_const_handle> visited{here};
  for (;;) {
    Dart_handle step = nullptr;
    PolylineProjection best{std::numeric_limits<double>::infinity(), 0.0};
    for (Dart_handle d : darts_leaving(lcc, here)) {
      if (lcc.is_free<2>(d)) continue;
      const Vertex_const_handle next = lcc.vertex_attribute(lcc.next(d));
      const PolylineProjection p = project_on_polyline(polyline, rest_of(next));
      const double edge_m = (rest_of(next) - rest_of(here)).norm();
      // forward, near the polyline (within one edge), closest first, then furthest along
      if (visited.count(next) || p.arc_length_m <= along_m + 1e-9 * edge_m ||
          p.distance_m > edge_m) {
        continue;
      }
      if (p.distance_m < best.distance_m ||
          (p.distance_m == best.distance_m && p.arc_length_m > best.arc_length_m)) {
        best = p;
        step = d;
      }
    }
    if (step == nullptr) return path;
    path.push_back(step);
    here = lcc.vertex_attribute(lcc.next(step));
    along_m = best.arc_length_m;
    visited.insert(here);
  }
}

}  // namespace

TearReport tear_edge(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings) {
  if (lcc.is_free<2>(dart)) {
    throw std::invalid_argument("tear_edge: the edge is on the cloth's border already");
  }
  const std::size_t particles_before = lcc.vertex_attributes().size();
  const Dart_handle other = lcc.opposite<2>(dart);
  lcc.unsew<2>(dart);  // duplicates the vertex attribute of a fan it breaks
  for (Dart_handle d : {dart, lcc.next(dart), other, lcc.next(other)}) {
    lcc.vertex_attribute(d)->info().on_crack = true;
  }
  update_around_faces(lcc, {dart, other}, settings);
  assert(is_valid_cloth(lcc));
  TearReport report;
  report.tears = 1;
  report.new_particles = static_cast<int>(lcc.vertex_attributes().size() - particles_before);
  return report;
}

TearReport tear(ClothComplex& lcc, const TearingOptions& options, int max_particles,
                const SpringSettings& settings) {
  TearReport report;
  if (!(options.strain_threshold > 0.0)) return report;
  std::set<Vertex_handle> touched;  // ends of edges torn in this pass
  std::vector<Vertex_handle> tips;
  for (const Overstretched& overstretched : overstretched_edges(lcc, options)) {
    if (report.tears >= options.max_tears_per_step) break;
    if (touched.count(overstretched.a) || touched.count(overstretched.b)) continue;
    const Vertex_handle v = breaking_end(lcc, overstretched);
    for (Dart_handle edge : crack_edges(lcc, v, options.min_piece_faces)) {
      if (report.tears >= options.max_tears_per_step) break;
      // the fracture's first edge may have changed that
      if (sheds_a_fragment(lcc, edge, options.min_piece_faces)) continue;
      const Vertex_handle far_end = lcc.vertex_attribute(lcc.next(edge));
      touched.insert(v);
      touched.insert(far_end);
      tips.push_back(far_end);
      add(report, tear_edge(lcc, edge, settings));
    }
  }
  if (options.tip_min_edge_length_m > 0.0) {
    for (Vertex_handle tip : tips) {
      report.tip_refinements +=
          refine_around_vertex(lcc, tip, options.tip_min_edge_length_m, max_particles, settings);
    }
  }
  return report;
}

TearReport cut_along(ClothComplex& lcc, const std::vector<Eigen::Vector3d>& polyline_m,
                     const SpringSettings& settings) {
  TearReport report;
  if (polyline_m.size() < 2 || lcc.vertex_attributes().empty()) return report;
  for (Dart_handle edge : cut_path(lcc, polyline_m)) {
    if (!lcc.is_free<2>(edge)) add(report, tear_edge(lcc, edge, settings));
  }
  return report;
}

int count_pieces(const ClothComplex& lcc) {
  int pieces = 0;
  for (auto d = lcc.one_dart_per_cell<3>().begin(); d != lcc.one_dart_per_cell<3>().end(); ++d) {
    ++pieces;
  }
  return pieces;
}

int count_boundary_edges(const ClothComplex& lcc) {
  int edges = 0;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.is_free<2>(d)) ++edges;
  }
  return edges;
}

}  // namespace tissu
