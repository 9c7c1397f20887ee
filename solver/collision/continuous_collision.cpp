#include "solver/collision/continuous_collision.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "solver/collision/primitive_distance.hpp"

namespace tissu {
namespace {

/// Closest points of the pair at time t: weights as in ContactPair.
Eigen::Vector4d closest_weights(const CandidatePair& pair, const PairMotion& m, double t) {
  if (pair.edge_edge) {
    const Eigen::Vector2d st =
        nearest_between_segments(m.at(0, t), m.at(1, t), m.at(2, t), m.at(3, t));
    return {1.0 - st[0], st[0], -(1.0 - st[1]), -st[1]};
  }
  const Eigen::Vector3d l = nearest_on_triangle(m.at(0, t), m.at(1, t), m.at(2, t), m.at(3, t));
  return {1.0, -l[0], -l[1], -l[2]};
}

Eigen::Vector3d relative_position(const PairMotion& m, const Eigen::Vector4d& w, double t) {
  return w[0] * m.at(0, t) + w[1] * m.at(1, t) + w[2] * m.at(2, t) + w[3] * m.at(3, t);
}

/// The two vectors whose cross product is the pair's geometric normal at time t: the triangle's
/// two edges from its first corner, or the two edges' directions.
std::pair<Eigen::Vector3d, Eigen::Vector3d> spanning_vectors(const CandidatePair& pair,
                                                             const PairMotion& m, double t) {
  if (pair.edge_edge) return {m.at(1, t) - m.at(0, t), m.at(3, t) - m.at(2, t)};
  return {m.at(2, t) - m.at(1, t), m.at(3, t) - m.at(1, t)};
}

/// The unit normal of the contact at time t, pointing to the side where the first primitive
/// started: the triangle's normal or the edges' common normal, or, where that is undefined
/// (parallel edges), the direction between the closest points.
Eigen::Vector3d oriented_normal(const CandidatePair& pair, const PairMotion& m,
                                const Eigen::Vector4d& w, double t) {
  const auto [u, v] = spanning_vectors(pair, m, t);
  Eigen::Vector3d n = u.cross(v);
  if (n.squaredNorm() <= 1e-12 * u.squaredNorm() * v.squaredNorm()) n = relative_position(m, w, t);
  if (!(n.squaredNorm() > 0.0)) n = relative_position(m, w, 0.0);
  if (!(n.squaredNorm() > 0.0)) return Eigen::Vector3d::UnitZ();
  n.normalize();
  return relative_position(m, w, 0.0).dot(n) < 0.0 ? Eigen::Vector3d(-n) : n;
}

/// Up to five roots in [0, 1], ascending (a root per piece between turning points, and t = 1).
struct UnitIntervalRoots {
  std::array<double, 5> t{};
  int count = 0;
  const double* begin() const { return t.data(); }
  const double* end() const { return t.data() + count; }
};

/// Roots in [0, 1] of c3 t^3 + c2 t^2 + c1 t + c0, ascending: the interval is cut at the turning
/// points, and each piece holding a sign change is bisected to double precision.
UnitIntervalRoots cubic_roots_in_unit_interval(double c3, double c2, double c1, double c0) {
  auto f = [&](double t) { return ((c3 * t + c2) * t + c1) * t + c0; };
  std::array<double, 4> cuts{0.0};
  int cut_count = 1;
  // turning points: 3 c3 t^2 + 2 c2 t + c1 = 0
  const double a = 3.0 * c3, b = 2.0 * c2, c = c1;
  if (std::abs(a) > 0.0) {
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant >= 0.0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
      for (double t : {q / a, q != 0.0 ? c / q : -1.0}) {
        if (t > 0.0 && t < 1.0) cuts[cut_count++] = t;
      }
    }
  } else if (std::abs(b) > 0.0 && -c / b > 0.0 && -c / b < 1.0) {
    cuts[cut_count++] = -c / b;
  }
  cuts[cut_count++] = 1.0;
  std::sort(cuts.begin(), cuts.begin() + cut_count);
  UnitIntervalRoots roots;
  for (int k = 0; k + 1 < cut_count; ++k) {
    double lo = cuts[k], hi = cuts[k + 1];
    double f_lo = f(lo);
    const double f_hi = f(hi);
    if (f_lo == 0.0) {
      roots.t[roots.count++] = lo;
      continue;
    }
    if ((f_lo < 0.0) == (f_hi < 0.0)) continue;
    for (int i = 0; i < 100 && hi - lo > 1e-15; ++i) {
      const double mid = 0.5 * (lo + hi);
      const double f_mid = f(mid);
      if ((f_mid < 0.0) == (f_lo < 0.0)) {
        lo = mid;
        f_lo = f_mid;
      } else {
        hi = mid;
      }
    }
    roots.t[roots.count++] = 0.5 * (lo + hi);
  }
  if (f(1.0) == 0.0) roots.t[roots.count++] = 1.0;
  return roots;
}

/// The largest relative displacement over the step of a corner of the first primitive and one of
/// the second (m).
double largest_relative_displacement_m(const CandidatePair& pair, const PairMotion& m) {
  const int first_size = pair.first_primitive_size();
  double largest_squared = 0.0;
  for (int i = 0; i < first_size; ++i) {
    for (int j = first_size; j < 4; ++j) {
      largest_squared =
          std::max(largest_squared, (m.displacement[i] - m.displacement[j]).squaredNorm());
    }
  }
  return std::sqrt(largest_squared);
}

}  // namespace

bool cubic_keeps_its_sign_on_unit_interval(double c3, double c2, double c1, double c0) {
  const double b0 = c0, b1 = c0 + c1 / 3.0, b2 = c0 + (2.0 * c1 + c2) / 3.0, b3 = c0 + c1 + c2 + c3;
  // the coefficients' rounding errors are a few ulps of the largest term
  const double margin = 1e-12 * (std::abs(c0) + std::abs(c1) + std::abs(c2) + std::abs(c3));
  return std::min({b0, b1, b2, b3}) > margin || std::max({b0, b1, b2, b3}) < -margin;
}

EndProximity proximity_at_end(const CandidatePair& pair, const PairMotion& motion,
                              double thickness_m) {
  const Eigen::Vector4d w = closest_weights(pair, motion, 1.0);
  const double distance_m = relative_position(motion, w, 1.0).norm();
  if (distance_m >= thickness_m) return {distance_m, std::nullopt};
  return {distance_m,
          ContactPair{pair.particle, w, oriented_normal(pair, motion, w, 1.0), distance_m}};
}

bool stays_farther_than(const CandidatePair& pair, const PairMotion& m, double distance_m) {
  const double end_distance_m = relative_position(m, closest_weights(pair, m, 1.0), 1.0).norm();
  return stays_farther_than(pair, m, distance_m, end_distance_m);
}

bool stays_farther_than(const CandidatePair& pair, const PairMotion& m, double distance_m,
                        double end_distance_at_least_m) {
  return end_distance_at_least_m - largest_relative_displacement_m(pair, m) > distance_m;
}

std::optional<ContactPair> first_impact(const CandidatePair& pair, const PairMotion& m,
                                        double tolerance_m) {
  // (a + t da) x (b + t db) . (c + t dc), relative to particle 0
  const Eigen::Vector3d a = m.start[1] - m.start[0], da = m.displacement[1] - m.displacement[0];
  const Eigen::Vector3d b = m.start[2] - m.start[0], db = m.displacement[2] - m.displacement[0];
  const Eigen::Vector3d c = m.start[3] - m.start[0], dc = m.displacement[3] - m.displacement[0];
  const Eigen::Vector3d axb = a.cross(b), mixed = a.cross(db) + da.cross(b), daxdb = da.cross(db);
  const double c0 = axb.dot(c);
  const double c1 = axb.dot(dc) + mixed.dot(c);
  const double c2 = mixed.dot(dc) + daxdb.dot(c);
  const double c3 = daxdb.dot(dc);
  if (cubic_keeps_its_sign_on_unit_interval(c3, c2, c1, c0)) return std::nullopt;  // never coplanar
  if (stays_farther_than(pair, m, tolerance_m)) return std::nullopt;  // coplanar but apart
  for (double t : cubic_roots_in_unit_interval(c3, c2, c1, c0)) {
    const Eigen::Vector4d w = closest_weights(pair, m, t);
    if (relative_position(m, w, t).norm() > tolerance_m) continue;
    const Eigen::Vector3d n = oriented_normal(pair, m, w, t);
    Eigen::Vector3d relative_displacement = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) relative_displacement += w[k] * m.displacement[k];
    if (relative_displacement.dot(n) >= 0.0) continue;  // touching but not closing in
    ContactPair contact{pair.particle, w, n, 0.0};
    return contact;
  }
  return std::nullopt;
}

}  // namespace tissu
