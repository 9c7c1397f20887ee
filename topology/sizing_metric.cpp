#include "topology/sizing_metric.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "topology/edge_measures.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/sizing_geometry.hpp"

namespace tissu {
namespace {

/// The turn of every interior edge, by the address of each of its two darts: each hinge is read
/// once, where the faces on either side of it would read it twice.
std::unordered_map<const void*, EdgeTurn> edge_turns(const ClothComplex& lcc, double lookahead_s) {
  std::unordered_map<const void*, EdgeTurn> turns;
  turns.reserve(2 * lcc.attributes<1>().size());
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    if (lcc.is_free<2>(d)) continue;
    const EdgeTurn turn = edge_turn(lcc, d, lookahead_s);
    turns[&*d] = turn;
    turns[&*lcc.opposite<2>(d)] = turn;
  }
  return turns;
}

/// The face's shape operators relative to rest (1/m), now and looking ahead, tensors in its rest
/// plane: 1 / (2 A) sum_e (theta_e - theta0_e) |e| t_e t_e^T over its interior edges.
std::pair<Eigen::Matrix3d, Eigen::Matrix3d> relative_shape_operators(
    const ClothComplex& lcc, Dart_const_handle face, const Eigen::Vector3d& unit_normal,
    double area_m2, const std::unordered_map<const void*, EdgeTurn>& turns) {
  const auto rest = [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); };
  Eigen::Matrix3d now = Eigen::Matrix3d::Zero(), ahead = Eigen::Matrix3d::Zero();
  Dart_const_handle e = face;
  for (int k = 0; k < 3; ++k, e = lcc.next(e)) {
    const auto turn = turns.find(&*e);
    if (turn == turns.end()) continue;  // a border edge
    const Eigen::Vector3d edge = rest(lcc.next(e)) - rest(e);
    const Eigen::Vector3d across = unit_normal.cross(edge).normalized();
    const Eigen::Matrix3d weight = (0.5 * edge.norm() / area_m2) * across * across.transpose();
    now += turn->second.now_rad * weight;
    ahead += turn->second.ahead_rad * weight;
  }
  return {now, ahead};
}

/// A metric clamped in a face's plane, with its larger eigenvalue there (1/m^2).
struct ClampedMetric {
  Eigen::Matrix3d metric_per_m2;
  double largest_per_m2;
};

/// `metric` with its eigenvalues in the plane of the orthonormal `frame` clamped to at most
/// `largest_per_m2` and at least the larger one over `max_aspect`^2. The 2 x 2 eigenproblem
/// [a b; b c] in closed form: lambda = m -+ r with m = (a + c) / 2, r = sqrt(((a - c) / 2)^2 +
/// b^2); the larger one's eigenvector is (lambda - c, b) when a >= c, else (b, lambda - a), whose
/// leading term is then at least r.
ClampedMetric clamped(const Eigen::Matrix3d& metric, const Eigen::Matrix<double, 3, 2>& frame,
                      double largest_per_m2, double max_aspect) {
  const Eigen::Matrix2d in_plane = frame.transpose() * metric * frame;
  const double a = in_plane(0, 0), b = in_plane(0, 1), c = in_plane(1, 1);
  const double mean = 0.5 * (a + c), radius = std::hypot(0.5 * (a - c), b);
  Eigen::Vector2d larger_axis =
      a >= c ? Eigen::Vector2d(mean + radius - c, b) : Eigen::Vector2d(b, mean + radius - a);
  larger_axis = radius > 0.0 ? larger_axis.normalized() : Eigen::Vector2d::UnitX();
  const double larger = std::min(std::max(mean + radius, 0.0), largest_per_m2);
  const double smaller =
      std::clamp(std::max(mean - radius, 0.0), larger / (max_aspect * max_aspect), larger);
  const Eigen::Vector3d along = frame * larger_axis;
  const Eigen::Vector3d across = frame * Eigen::Vector2d(-larger_axis[1], larger_axis[0]);
  return {larger * along * along.transpose() + smaller * across * across.transpose(), larger};
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
  const std::unordered_map<const void*, EdgeTurn> turns =
      o.curvature_threshold_rad > 0.0 ? edge_turns(lcc, o.lookahead_s)
                                      : std::unordered_map<const void*, EdgeTurn>{};
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
      const auto [s_now, s_ahead] =
          relative_shape_operators(lcc, d, normal.normalized(), area_m2, turns);
      Eigen::Matrix3d curvature = over * s_now * s_now;
      shares.curvature = curvature.trace();
      if (o.lookahead_s > 0.0) {
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
