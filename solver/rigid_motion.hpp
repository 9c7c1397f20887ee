#pragma once
/// \file
/// Rigid motions that follow keyframes: the handles that move pinned particles and the obstacles
/// that move through the scene. CGAL-free.

#include <Eigen/Core>
#include <vector>

namespace tissu {

/// A pose of a rigid motion: x -> pivot + translation + rotation (x - pivot).
struct RigidPose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d pivot_m = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& x) const {
    return pivot_m + translation_m + rotation * (x - pivot_m);
  }
  Eigen::Vector3d apply_inverse(const Eigen::Vector3d& y) const {
    return pivot_m + rotation.transpose() * (y - pivot_m - translation_m);
  }
};

/// One keyframe: at `time_s` the moving thing is rotated by `rotation_rad` about the motion's
/// pivot, then translated by `translation_m`, from where it was at t = 0 (its place in the
/// scenario). The rotation is a rotation vector (unit axis times angle, rad): its angle may exceed
/// a turn, so that keys of 0, 360 and 720 degrees spin twice.
struct RigidKey {
  double time_s = 0.0;
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_rad = Eigen::Vector3d::Zero();
};

enum class KeyInterpolation {
  linear,  ///< straight between keys: the velocity jumps at each key
  smooth,  ///< cubic Hermite with Catmull-Rom tangents, zero at the first and last keys: C1
};

/// A rigid motion through keyframes, held before the first and after the last, plus a constant
/// drift: translation(t) = keys(t) + drift t. Translations and rotation vectors are interpolated
/// separately; interpolating rotation vectors is exact for rotations about one axis (a door, a
/// turntable, an arm raised), and for keys about different axes gives a continuous rotation
/// through the keys (not the shortest one).
struct RigidMotion {
  std::vector<RigidKey> keys;  ///< increasing times; none: the drift only
  KeyInterpolation interpolation = KeyInterpolation::linear;
  Eigen::Vector3d pivot_m = Eigen::Vector3d::Zero();        ///< rotations are about it (m)
  Eigen::Vector3d drift_m_per_s = Eigen::Vector3d::Zero();  ///< constant velocity added (m/s)

  /// Whether it ever rotates (then points move by more than one translation).
  bool rotates() const;
  /// Whether it moves at all.
  bool moves() const { return !keys.empty() || !drift_m_per_s.isZero(); }

  RigidPose pose(double time_s) const;
  /// Where the point at `x` at time t0 is at time t1 (m).
  Eigen::Vector3d carry(const Eigen::Vector3d& x, double t0_s, double t1_s) const;
  /// Velocity at `time_s` of the moving point that is at `x` then (m/s): the translation's rate
  /// plus omega x (x - pivot - translation). Between linear keys it is the segment's; at a
  /// linear key, the segment's that starts there.
  Eigen::Vector3d point_velocity(const Eigen::Vector3d& x, double time_s) const;
  /// An upper bound on the speed of any point within `reach_m` of the pivot's moving place, over
  /// the whole motion (m/s).
  double fastest_speed_m_per_s(double reach_m) const;
};

/// Rotation matrix of a rotation vector (unit axis times angle, rad): Rodrigues' formula.
Eigen::Matrix3d rotation_of(const Eigen::Vector3d& rotation_rad);

}  // namespace tissu
