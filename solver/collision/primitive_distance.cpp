#include "solver/collision/primitive_distance.hpp"

#include <algorithm>
#include <limits>

namespace tissu {

double nearest_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& from,
                          const Eigen::Vector3d& to) {
  const Eigen::Vector3d d = to - from;
  const double length2 = d.squaredNorm();
  return length2 > 0.0 ? std::clamp((p - from).dot(d) / length2, 0.0, 1.0) : 0.0;
}

Eigen::Vector3d nearest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac);
  const double d20 = ap.dot(ab), d21 = ap.dot(ac);
  const double det = d00 * d11 - d01 * d01;
  if (det > 1e-14 * d00 * d11) {
    const double v = (d11 * d20 - d01 * d21) / det;
    const double w = (d00 * d21 - d01 * d20) / det;
    if (v >= 0.0 && w >= 0.0 && v + w <= 1.0) return {1.0 - v - w, v, w};
  }
  // outside (or degenerate): the nearest point lies on one of the three edges
  const double t_ab = nearest_on_segment(p, a, b);
  const double t_bc = nearest_on_segment(p, b, c);
  const double t_ca = nearest_on_segment(p, c, a);
  const Eigen::Vector3d candidates[3] = {
      {1.0 - t_ab, t_ab, 0.0}, {0.0, 1.0 - t_bc, t_bc}, {t_ca, 0.0, 1.0 - t_ca}};
  Eigen::Vector3d best = candidates[0];
  double best_m2 = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& l : candidates) {
    const double m2 = (l[0] * a + l[1] * b + l[2] * c - p).squaredNorm();
    if (m2 < best_m2) best_m2 = m2, best = l;
  }
  return best;
}

Eigen::Vector2d nearest_between_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                         const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  if (a <= 0.0 && e <= 0.0) return {0.0, 0.0};
  if (a <= 0.0) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (e <= 0.0) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = d1.dot(d2);
  const double denominator = a * e - b * b;  // >= 0; 0 when parallel
  double s =
      denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

}  // namespace tissu
