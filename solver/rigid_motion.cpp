#include "solver/rigid_motion.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace tissu {
namespace {

/// A keyed vector and its time derivative at one instant.
struct Interpolated {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate = Eigen::Vector3d::Zero();  ///< per second
};

/// Catmull-Rom tangent at key k (per second): (p[k+1] - p[k-1]) / (t[k+1] - t[k-1]), zero at the
/// first and last keys so that the motion starts and stops without a jump in velocity.
template <class Field>
Eigen::Vector3d tangent(const std::vector<RigidKey>& keys, std::size_t k, Field field) {
  if (k == 0 || k + 1 >= keys.size()) return Eigen::Vector3d::Zero();
  return (field(keys[k + 1]) - field(keys[k - 1])) / (keys[k + 1].time_s - keys[k - 1].time_s);
}

/// The keyed field at `time_s`: held before the first and after the last key; linear or cubic
/// Hermite between (Catmull & Rom 1974; the Hermite basis h00, h10, h01, h11 in s in [0, 1]).
template <class Field>
Interpolated interpolate(const std::vector<RigidKey>& keys, KeyInterpolation interpolation,
                         double time_s, Field field) {
  if (keys.empty()) return {};
  const auto after = std::upper_bound(keys.begin(), keys.end(), time_s,
                                      [](double t, const RigidKey& key) { return t < key.time_s; });
  if (after == keys.begin()) return {field(keys.front()), Eigen::Vector3d::Zero()};
  if (after == keys.end()) return {field(keys.back()), Eigen::Vector3d::Zero()};
  const std::size_t k = static_cast<std::size_t>(after - keys.begin()) - 1;
  const double duration_s = keys[k + 1].time_s - keys[k].time_s;
  const double s = (time_s - keys[k].time_s) / duration_s;
  const Eigen::Vector3d p0 = field(keys[k]);
  const Eigen::Vector3d p1 = field(keys[k + 1]);
  if (interpolation == KeyInterpolation::linear) {
    return {(1.0 - s) * p0 + s * p1, (p1 - p0) / duration_s};
  }
  const Eigen::Vector3d m0 = duration_s * tangent(keys, k, field);
  const Eigen::Vector3d m1 = duration_s * tangent(keys, k + 1, field);
  const double s2 = s * s, s3 = s2 * s;
  const Eigen::Vector3d value = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 +
                                (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
  const Eigen::Vector3d rate = ((6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * m0 +
                                (-6 * s2 + 6 * s) * p1 + (3 * s2 - 2 * s) * m1) /
                               duration_s;
  return {value, rate};
}

const auto translation_of = [](const RigidKey& key) { return key.translation_m; };
const auto rotation_vector_of = [](const RigidKey& key) { return key.rotation_rad; };

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& r) {
  Eigen::Matrix3d m;
  m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return m;
}

/// Angular velocity (rad/s, world frame) of R(t) = exp([r(t)]x): omega = J_l(r) dr/dt, with the
/// left Jacobian of SO(3) J_l = I + (1 - cos a)/a^2 [r]x + (a - sin a)/a^3 [r]x^2, a = |r|
/// (Chirikjian 2011, "Stochastic Models, Information Theory, and Lie Groups", vol. 2, 10.6).
Eigen::Vector3d angular_velocity(const Eigen::Vector3d& r, const Eigen::Vector3d& r_rate) {
  const double a = r.norm();
  // series below 1e-4 rad, where the closed forms lose their digits
  const double c1 = a < 1e-4 ? 0.5 - a * a / 24.0 : (1.0 - std::cos(a)) / (a * a);
  const double c2 = a < 1e-4 ? 1.0 / 6.0 - a * a / 120.0 : (a - std::sin(a)) / (a * a * a);
  const Eigen::Matrix3d k = cross_matrix(r);
  return (Eigen::Matrix3d::Identity() + c1 * k + c2 * k * k) * r_rate;
}

}  // namespace

Eigen::Matrix3d rotation_of(const Eigen::Vector3d& rotation_rad) {
  const double angle = rotation_rad.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, rotation_rad / angle).toRotationMatrix();
}

bool RigidMotion::rotates() const {
  return std::any_of(keys.begin(), keys.end(),
                     [](const RigidKey& key) { return !key.rotation_rad.isZero(); });
}

RigidPose RigidMotion::pose(double time_s) const {
  RigidPose pose;
  pose.pivot_m = pivot_m;
  pose.translation_m =
      drift_m_per_s * time_s + interpolate(keys, interpolation, time_s, translation_of).value;
  pose.rotation = rotation_of(interpolate(keys, interpolation, time_s, rotation_vector_of).value);
  return pose;
}

Eigen::Vector3d RigidMotion::carry(const Eigen::Vector3d& x, double t0_s, double t1_s) const {
  return pose(t1_s).apply(pose(t0_s).apply_inverse(x));
}

Eigen::Vector3d RigidMotion::point_velocity(const Eigen::Vector3d& x, double time_s) const {
  const Interpolated translation = interpolate(keys, interpolation, time_s, translation_of);
  const Interpolated rotation = interpolate(keys, interpolation, time_s, rotation_vector_of);
  const Eigen::Vector3d omega = angular_velocity(rotation.value, rotation.rate);
  const Eigen::Vector3d centre = pivot_m + translation.value + drift_m_per_s * time_s;
  return translation.rate + drift_m_per_s + omega.cross(x - centre);
}

double RigidMotion::fastest_speed_m_per_s(double reach_m) const {
  // |omega| <= |dr/dt| (the left Jacobian is an average of rotations); the rates sampled finely
  // over each segment, since a Hermite segment's fastest instant lies between its keys
  constexpr int samples_per_segment = 64;
  double fastest_m_per_s = 0.0;
  for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
    for (int i = 0; i <= samples_per_segment; ++i) {
      const double t = keys[k].time_s + (keys[k + 1].time_s - keys[k].time_s) * i /
                                            static_cast<double>(samples_per_segment);
      const double t_inside = std::min(t, std::nextafter(keys[k + 1].time_s, keys[k].time_s));
      const double speed =
          interpolate(keys, interpolation, t_inside, translation_of).rate.norm() +
          interpolate(keys, interpolation, t_inside, rotation_vector_of).rate.norm() * reach_m;
      fastest_m_per_s = std::max(fastest_m_per_s, speed);
    }
  }
  return drift_m_per_s.norm() + fastest_m_per_s;
}

}  // namespace tissu
