#include "topology/sizing_metric.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "topology/edge_measures.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/sizing_geometry.hpp"

namespace tissu {
namespace {

/// The face's shape operator relative to rest (1/m), a tensor in its rest plane:
/// 1 / (2 A) sum_e (theta_e - theta0_e) |e| t_e t_e^T over its interior edges, theta read from
/// the positions `at` gives.
template <class Position>
Eigen::Matrix3d relative_shape_operator(const ClothComplex& lcc, Dart_const_handle face,
                                        const Eigen::Vector3d& unit_normal, double area_m2,
                                        Position at) {
  const auto rest = [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); };
  Eigen::Matrix3d shape = Eigen::Matrix3d::Zero();
  for (auto e = lcc.darts_of_orbit<1>(face).begin(); e != lcc.darts_of_orbit<1>(face).end(); ++e) {
    if (lcc.is_free<2>(e)) continue;
    const Eigen::Vector3d edge = rest(lcc.next(e)) - rest(e);
    const Eigen::Vector3d across = unit_normal.cross(edge).normalized();
    const double turn_rad = wrapped(signed_dihedral(lcc, e, at) - signed_dihedral(lcc, e, rest));
    shape += 0.5 * turn_rad * edge.norm() * across * across.transpose();
  }
  return shape / area_m2;
}

/// A metric clamped in a face's plane, with its larger eigenvalue there (1/m^2).
struct ClampedMetric {
  Eigen::Matrix3d metric_per_m2;
  double largest_per_m2;
};

/// `metric` with its eigenvalues in the plane of the orthonormal `frame` clamped to at most
/// `largest_per_m2` and at least the larger one over `max_aspect`^2.
ClampedMetric clamped(const Eigen::Matrix3d& metric, const Eigen::Matrix<double, 3, 2>& frame,
                      double largest_per_m2, double max_aspect) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> in_plane(frame.transpose() * metric * frame);
  Eigen::Vector2d lambda = in_plane.eigenvalues().cwiseMax(0.0);  // ascending
  lambda[1] = std::min(lambda[1], largest_per_m2);
  lambda[0] = std::clamp(lambda[0], lambda[1] / (max_aspect * max_aspect), lambda[1]);
  const Eigen::Matrix<double, 3, 2> axes = frame * in_plane.eigenvectors();
  return {axes * lambda.asDiagonal() * axes.transpose(), lambda[1]};
}

}  // namespace

double metric_length2(const Eigen::Matrix3d& metric_per_m2, const Point3& a_m, const Point3& b_m) {
  const Eigen::Vector3d e = to_eigen(b_m) - to_eigen(a_m);
  return e.dot(metric_per_m2 * e);
}

void compute_sizing_metric(ClothComplex& lcc, const RefinementOptions& o,
                           const SizingInputs& inputs) {
  const bool obstacles = o.obstacle_proximity && inputs.obstacles && !inputs.obstacles->empty();
  const NearestPlanes planes = obstacles ? nearest_planes(lcc, inputs) : NearestPlanes{};
  const double floor_per_m2 =
      o.max_edge_length_m > 0.0 ? 1.0 / (o.max_edge_length_m * o.max_edge_length_m) : 0.0;
  const auto now = [&](Dart_const_handle e) { return to_eigen(lcc.point(e)); };
  const auto ahead = [&](Dart_const_handle e) {
    return Eigen::Vector3d(to_eigen(lcc.point(e)) +
                           o.lookahead_s * to_eigen(lcc.vertex_attribute(e)->info().velocity));
  };
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    FaceRest& face = lcc.info<2>(d);
    face.sizing_metric_per_m2.setZero();
    face.sizing_per_m2 = 0.0;
    face.sizing_term = SizingTerm::none;
    if (lcc.darts_of_orbit<1>(d).size() != 3) continue;
    const auto rest =
        corners(lcc, d, [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); });
    const Eigen::Vector3d normal = (rest[1] - rest[0]).cross(rest[2] - rest[0]);
    const double area_m2 = 0.5 * normal.norm();
    if (!(area_m2 > 0.0)) continue;
    Eigen::Matrix<double, 3, 2> frame;
    frame.col(0) = (rest[1] - rest[0]).normalized();
    frame.col(1) = normal.normalized().cross(frame.col(0));
    const Eigen::Matrix3d in_plane = frame * frame.transpose();  // the projector onto the plane

    TermShares shares;
    Eigen::Matrix3d metric = floor_per_m2 * in_plane;
    if (o.curvature_threshold_rad > 0.0) {
      const double over = 1.0 / (o.curvature_threshold_rad * o.curvature_threshold_rad);
      const Eigen::Matrix3d s_now =
          relative_shape_operator(lcc, d, normal.normalized(), area_m2, now);
      Eigen::Matrix3d curvature = over * s_now * s_now;
      shares.curvature = curvature.trace();
      if (o.lookahead_s > 0.0) {
        const Eigen::Matrix3d s_ahead =
            relative_shape_operator(lcc, d, normal.normalized(), area_m2, ahead);
        const Eigen::Matrix3d looking_ahead = over * s_ahead * s_ahead;
        if (looking_ahead.trace() > curvature.trace()) {
          shares.velocity = looking_ahead.trace() - curvature.trace();
          curvature = looking_ahead;
        }
      }
      metric += curvature;
    }
    double longest_m = 0.0;
    double largest_strain = 0.0;
    for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
      longest_m = std::max(longest_m, edge_rest_length_m(lcc, e));
      largest_strain = std::max(largest_strain, edge_strain(lcc, e));
    }
    if (o.strain_threshold > 0.0) {
      const double over = largest_strain / (o.strain_threshold * longest_m);
      shares.strain = 2.0 * over * over;  // the trace of over^2 in both directions of the plane
      metric += over * over * in_plane;
    }
    if (obstacles) {
      const Eigen::Matrix3d near = obstacle_metric(lcc, d, planes);
      shares.obstacles = near.trace();
      metric += near;
    }
    const double largest_per_m2 = 1.0 / (o.min_edge_length_m * o.min_edge_length_m);
    const ClampedMetric wanted = clamped(metric, frame, largest_per_m2, o.max_aspect_ratio);
    face.sizing_metric_per_m2 = wanted.metric_per_m2;
    face.sizing_per_m2 = wanted.largest_per_m2;
    bool under_half = true;  // along every edge: collapsing at the default hysteresis may remove it
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = rest[(k + 1) % 3] - rest[k];
      under_half = under_half && e.dot(face.sizing_metric_per_m2 * e) < 0.25;
    }
    face.sizing_term = under_half ? SizingTerm::none : largest_share(shares, 2.0 * floor_per_m2);
  }
}

}  // namespace tissu
