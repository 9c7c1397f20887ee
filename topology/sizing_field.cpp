#include "topology/sizing_field.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "topology/edge_measures.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/rest_geometry.hpp"

namespace tissu {
namespace {

constexpr double pi = 3.14159265358979323846;

/// The three corners of the dart's triangle, from the dart's origin, as read by `at`.
template <class Position>
std::array<Eigen::Vector3d, 3> corners(const ClothComplex& lcc, Dart_const_handle d, Position at) {
  return {at(d), at(lcc.next(d)), at(lcc.next(lcc.next(d)))};
}

/// Signed angle (rad) between the normals of the faces of `d` and of its twin about the edge
/// a -> b of `d`, with the corners of each face from `at`: 0 flat, positive folding one way.
template <class Position>
double signed_dihedral(const ClothComplex& lcc, Dart_const_handle d, Position at) {
  const auto f = corners(lcc, d, at);
  const auto g = corners(lcc, lcc.opposite<2>(d), at);
  const Eigen::Vector3d n1 = (f[1] - f[0]).cross(f[2] - f[0]);
  const Eigen::Vector3d n2 = (g[1] - g[0]).cross(g[2] - g[0]);
  const Eigen::Vector3d edge = f[1] - f[0];
  const double length = edge.norm();
  if (!(length > 0.0) || !(n1.squaredNorm() > 0.0) || !(n2.squaredNorm() > 0.0)) return 0.0;
  return std::atan2(n1.cross(n2).dot(edge) / length, n1.dot(n2));
}

/// `angle` wrapped into [-pi, pi] (rad).
double wrapped(double angle) {
  return std::remainder(angle, 2.0 * pi);
}

Eigen::Vector3d centroid(const std::array<Eigen::Vector3d, 3>& c) {
  return (c[0] + c[1] + c[2]) / 3.0;
}

/// Curvature (1/m) of the dart's interior edge relative to rest, |theta - theta0| / delta0, now
/// and at x + lookahead v (0 when lookahead_s is 0).
struct RelativeCurvature {
  double now_per_m = 0.0;
  double ahead_per_m = 0.0;
};

RelativeCurvature relative_curvature(const ClothComplex& lcc, Dart_const_handle d,
                                     double lookahead_s) {
  const auto rest = [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); };
  const auto now = [&](Dart_const_handle e) { return to_eigen(lcc.point(e)); };
  const double delta_m =
      (centroid(corners(lcc, d, rest)) - centroid(corners(lcc, lcc.opposite<2>(d), rest))).norm();
  if (!(delta_m > 0.0)) return {};
  const double rest_angle = signed_dihedral(lcc, d, rest);
  RelativeCurvature kappa;
  kappa.now_per_m = std::abs(wrapped(signed_dihedral(lcc, d, now) - rest_angle)) / delta_m;
  if (lookahead_s > 0.0) {
    const auto ahead = [&](Dart_const_handle e) {
      return Eigen::Vector3d(to_eigen(lcc.point(e)) +
                             lookahead_s * to_eigen(lcc.vertex_attribute(e)->info().velocity));
    };
    kappa.ahead_per_m = std::abs(wrapped(signed_dihedral(lcc, d, ahead) - rest_angle)) / delta_m;
  }
  return kappa;
}

double longest_rest_edge_m(const ClothComplex& lcc, Dart_const_handle d) {
  double longest = 0.0;
  for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
    longest = std::max(longest, edge_rest_length_m(lcc, e));
  }
  return longest;
}

/// The tangent plane of the obstacle nearest a particle: a point on it and its unit normal, and the
/// obstacle's thickness (m).
struct NearestPlane {
  Eigen::Vector3d point;
  Eigen::Vector3d normal;
  double thickness_m = 0.0;
};

NearestPlane nearest_plane(const std::vector<Obstacle>& obstacles, const Eigen::Vector3d& x,
                           double time_s) {
  NearestPlane best{x, Eigen::Vector3d::UnitZ(), 0.0};
  double best_distance_m = std::numeric_limits<double>::infinity();
  for (const Obstacle& obstacle : obstacles) {
    const SurfaceDistance s = surface_distance(obstacle, x, time_s);
    if (s.distance_m < best_distance_m) {
      best_distance_m = s.distance_m;
      best = {x - s.distance_m * s.normal, s.normal, obstacle.thickness_m};
    }
  }
  return best;
}

/// ARCSim's obstacle metric asks for an edge L <= sqrt(2 R t) on cloth lying on a surface of
/// radius R at the contact thickness t (its heights grow as d^2 / 2R from a corner at t, so
/// |grad h|^2 / h^2 ~ L^2 / (4 R^2 t^2)). What the mesh needs is that its faces' chords stay within
/// that thickness: the sagitta L^2 / (8 R) of a face of longest edge L (circumradius L / 2 for the
/// right triangles of bisection) at most t, so L <= sqrt(8 R t), twice as long: the metric / 16.
/// On the drape this keeps 1,385 particles where the metric alone made 1,958, and the ball does
/// not show through (docs/benchmarks.md, "the drape at equal steps").
constexpr double sagitta_scale = 1.0 / 16.0;

/// The obstacle term: ARCSim's obstacle metric, isotropic, the mean over the triangle's corners v
/// of |grad h_v|^2 / h_v(v)^2, h_v the heights of the corners above v's nearest plane, the
/// gradient taken in rest space, times sagitta_scale (1/m^2).
double obstacle_term(const ClothComplex& lcc, Dart_const_handle d,
                     const std::unordered_map<const void*, NearestPlane>& planes) {
  const auto rest =
      corners(lcc, d, [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); });
  const auto now = corners(lcc, d, [&](Dart_const_handle e) { return to_eigen(lcc.point(e)); });
  Eigen::Matrix<double, 3, 2> edges;
  edges << rest[1] - rest[0], rest[2] - rest[0];
  const Eigen::Matrix2d gram = edges.transpose() * edges;
  if (!(std::abs(gram.determinant()) > 0.0)) return 0.0;
  const Eigen::Matrix2d gram_inverse = gram.inverse();
  std::array<Dart_const_handle, 3> darts{d, lcc.next(d), lcc.next(lcc.next(d))};
  double sum = 0.0;
  for (int v = 0; v < 3; ++v) {
    const NearestPlane& plane = planes.at(&*lcc.vertex_attribute(darts[v]));
    std::array<double, 3> h;
    for (int k = 0; k < 3; ++k) h[k] = (now[k] - plane.point).dot(plane.normal);
    const Eigen::Vector2d dh(h[1] - h[0], h[2] - h[0]);
    const double height_m = std::max(h[v], plane.thickness_m);
    if (height_m > 0.0) sum += dh.dot(gram_inverse * dh) / (height_m * height_m);
  }
  return sagitta_scale * sum / 3.0;
}

/// Each term's share of a face's sizing (1/m^2): the largest over its edges for the edge terms.
struct TermShares {
  double curvature = 0.0;
  double velocity = 0.0;  ///< what looking ahead adds to the curvature term
  double strain = 0.0;
  double obstacles = 0.0;
};

/// The term with the largest share, or the maximum edge length when its floor is above them all;
/// none where even the face's parent, of longest edge sqrt(2) L (bisection halves a right
/// triangle at its hypotenuse), would be under half the target: 2 L^2 sizing < 1/4, where
/// coarsening at the default hysteresis (0.5) may merge the face back.
SizingTerm leading_term(const TermShares& shares, double floor_per_m2, double sizing_per_m2,
                        double longest_m) {
  if (2.0 * longest_m * longest_m * sizing_per_m2 < 0.25) return SizingTerm::none;
  const std::array<std::pair<double, SizingTerm>, 5> terms{{
      {shares.curvature, SizingTerm::curvature},
      {shares.velocity, SizingTerm::velocity},
      {shares.strain, SizingTerm::strain},
      {shares.obstacles, SizingTerm::obstacles},
      {floor_per_m2, SizingTerm::max_edge_length},
  }};
  return std::max_element(terms.begin(), terms.end(),
                          [](const auto& a, const auto& b) { return a.first < b.first; })
      ->second;
}

}  // namespace

void compute_sizing(ClothComplex& lcc, const RefinementOptions& o, const SizingInputs& inputs) {
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    f->info().sizing_per_m2 = 0.0;
  }
  std::unordered_map<const void*, TermShares> shares;
  shares.reserve(lcc.attributes<2>().size());
  // curvature and strain: per face, the largest over its edges
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    const bool interior = !lcc.is_free<2>(d);
    double now_term = 0.0;    // (kappa now / angle)^2 (1/m^2)
    double ahead_term = 0.0;  // (kappa ahead / angle)^2 (1/m^2)
    if (o.curvature_threshold_rad > 0.0 && interior) {
      const RelativeCurvature kappa = relative_curvature(lcc, d, o.lookahead_s);
      const double now_over = kappa.now_per_m / o.curvature_threshold_rad;
      const double ahead_over = kappa.ahead_per_m / o.curvature_threshold_rad;
      now_term = now_over * now_over;
      ahead_term = ahead_over * ahead_over;
    }
    const double curvature_term = std::max(now_term, ahead_term);
    const double strain_over =
        o.strain_threshold > 0.0 ? edge_strain(lcc, d) / o.strain_threshold : 0.0;
    auto raise = [&](Dart_handle side) {
      const double face_m = longest_rest_edge_m(lcc, side);
      const double strain_term = strain_over * strain_over / (face_m * face_m);
      double& sizing = lcc.info<2>(side).sizing_per_m2;
      sizing = std::max(sizing, curvature_term + strain_term);
      TermShares& share = shares[&*lcc.attribute<2>(side)];
      share.curvature = std::max(share.curvature, now_term);
      share.velocity = std::max(share.velocity, curvature_term - now_term);
      share.strain = std::max(share.strain, strain_term);
    };
    raise(d);
    if (interior) raise(lcc.opposite<2>(d));
  }
  std::unordered_map<const void*, NearestPlane> planes;
  const bool obstacles = o.obstacle_proximity && inputs.obstacles && !inputs.obstacles->empty();
  if (obstacles) {
    planes.reserve(lcc.vertex_attributes().size());
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      planes[&*v] = nearest_plane(*inputs.obstacles, to_eigen(v->point()), inputs.time_s);
    }
  }
  const double floor_per_m2 =
      o.max_edge_length_m > 0.0 ? 1.0 / (o.max_edge_length_m * o.max_edge_length_m) : 0.0;
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    FaceRest& face = lcc.info<2>(d);
    TermShares& share = shares[&*lcc.attribute<2>(d)];
    if (obstacles && lcc.darts_of_orbit<1>(d).size() == 3) {
      share.obstacles = obstacle_term(lcc, d, planes);
      face.sizing_per_m2 += share.obstacles;
    }
    face.sizing_per_m2 = std::max(face.sizing_per_m2, floor_per_m2);
    face.sizing_term =
        leading_term(share, floor_per_m2, face.sizing_per_m2, longest_rest_edge_m(lcc, d));
  }
}

double face_metric_length2(const ClothComplex& lcc, Dart_const_handle d) {
  const double longest_m = longest_rest_edge_m(lcc, d);
  return longest_m * longest_m * lcc.info<2>(d).sizing_per_m2;
}

}  // namespace tissu
