#include "topology/sizing_geometry.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "topology/eigen_conversions.hpp"
#include "topology/rest_geometry.hpp"

namespace tissu {

double wrapped(double angle) {
  constexpr double pi = 3.14159265358979323846;
  // a difference of two dihedral angles is within 2 pi: there one exact subtraction (Sterbenz)
  // gives what remainder() gives (but +0 for -2 pi), without its cost; below 9 < 3 pi, away from
  // its tie to even
  constexpr double within_rad = 9.0;
  if (std::abs(angle) <= pi) return angle;
  if (angle > pi && angle < within_rad) return angle - 2.0 * pi;
  if (angle < -pi && angle > -within_rad) return angle + 2.0 * pi;
  return std::remainder(angle, 2.0 * pi);
}

EdgeTurn edge_turn(const ClothComplex& lcc, Dart_const_handle d, double lookahead_s) {
  const auto rest = [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); };
  const auto now = [&](Dart_const_handle e) { return to_eigen(lcc.point(e)); };
  const double rest_rad = signed_dihedral(lcc, d, rest);
  EdgeTurn turn;
  turn.now_rad = wrapped(signed_dihedral(lcc, d, now) - rest_rad);
  if (lookahead_s > 0.0) {
    const auto ahead = [&](Dart_const_handle e) {
      return Eigen::Vector3d(to_eigen(lcc.point(e)) +
                             lookahead_s * to_eigen(lcc.vertex_attribute(e)->info().velocity));
    };
    turn.ahead_rad = wrapped(signed_dihedral(lcc, d, ahead) - rest_rad);
  }
  return turn;
}

namespace {

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

}  // namespace

NearestPlanes nearest_planes(const ClothComplex& lcc, const SizingInputs& inputs) {
  NearestPlanes planes;
  planes.reserve(lcc.vertex_attributes().size());
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    planes[&*v] = nearest_plane(*inputs.obstacles, to_eigen(v->point()), inputs.time_s);
  }
  return planes;
}

Eigen::Matrix3d obstacle_metric(const ClothComplex& lcc, Dart_const_handle d,
                                const NearestPlanes& planes) {
  const auto rest =
      corners(lcc, d, [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); });
  const auto now = corners(lcc, d, [&](Dart_const_handle e) { return to_eigen(lcc.point(e)); });
  Eigen::Matrix<double, 3, 2> edges;
  edges << rest[1] - rest[0], rest[2] - rest[0];
  const Eigen::Matrix2d gram = edges.transpose() * edges;
  Eigen::Matrix3d metric = Eigen::Matrix3d::Zero();
  if (!(std::abs(gram.determinant()) > 0.0)) return metric;
  // the gradient of a linear function over the face, in rest space: E G^-1 (its changes along E)
  const Eigen::Matrix<double, 3, 2> to_gradient = edges * gram.inverse();
  std::array<Dart_const_handle, 3> darts{d, lcc.next(d), lcc.next(lcc.next(d))};
  for (int v = 0; v < 3; ++v) {
    const NearestPlane& plane = planes.at(&*lcc.vertex_attribute(darts[v]));
    std::array<double, 3> h;
    for (int k = 0; k < 3; ++k) h[k] = (now[k] - plane.point).dot(plane.normal);
    const Eigen::Vector3d gradient = to_gradient * Eigen::Vector2d(h[1] - h[0], h[2] - h[0]);
    const double height_m = std::max(h[v], plane.thickness_m);
    if (height_m > 0.0) metric += gradient * gradient.transpose() / (height_m * height_m);
  }
  return sagitta_scale * metric / 3.0;
}

SizingTerm largest_share(const TermShares& shares, double floor_per_m2) {
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

}  // namespace tissu
