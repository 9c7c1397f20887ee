#pragma once
/// \file
/// Energy, force and Jacobians of one spring between particles i and j (header-only, inline).
///
/// Notation: d = xi - xj (m), u = d / |d|, k the stiffness (N/m), l0 the rest length (m),
/// nu the viscous coefficient (N s/m). The course (reference/mass-spring-lecture.md, "Forces des
/// ressorts") writes the elastic force as k (|d| - l0) u and the viscous one as
/// nu ((vi - vj) . u) u, leaving the sign to the reader; here every function returns the force
/// *on particle i*, with the sign that pulls i toward j when the spring is stretched and resists
/// the relative velocity along the spring. The force on j is the opposite.

#include <Eigen/Core>

#include "solver/forces/symmetric_block_matrix.hpp"

namespace tissu {

/// Below this length (m) a spring has no direction: its force and Jacobians are returned as zero
/// rather than NaN.
inline constexpr double spring_length_epsilon = 1e-12;

/// Elastic energy of a Hookean spring, E = 1/2 k (|xi - xj| - l0)^2 (J).
/// Source: Hooke's law; course "Projective Dynamics", W = sum |(pi - pj) - d|^2 per spring.
inline double spring_energy(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj, double k,
                            double l0) {
  const double stretch = (xi - xj).norm() - l0;
  return 0.5 * k * stretch * stretch;
}

/// Elastic force on i (N): f_i = -dE/dxi = -k (|d| - l0) d / |d|, d = xi - xj.
/// Source: course "Forces des ressorts" (written there as k (|d| - l) d/|d| with the opposite sign
/// convention); this sign pulls i toward j when |d| > l0. Zero when |d| < spring_length_epsilon.
inline Eigen::Vector3d spring_force(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj, double k,
                                    double l0) {
  const Eigen::Vector3d d = xi - xj;
  const double length = d.norm();
  if (length < spring_length_epsilon) return Eigen::Vector3d::Zero();
  return (-k * (length - l0) / length) * d;
}

/// Jacobian of the elastic force on i with respect to xi, 3x3 (N/m):
/// df_i/dxi = -k [ (1 - l0/|d|) (I - u u^T) + u u^T ].
/// The other blocks follow: df_i/dxj = df_j/dxi = -df_i/dxi and df_j/dxj = df_i/dxi.
/// Source: Baraff & Witkin 1998, "Large steps in cloth simulation" (force derivatives of a
/// condition C = |d| - l0); Choi & Ko 2002, "Stable but responsive cloth" (spring Jacobian).
/// It is symmetric but indefinite when the spring is compressed (|d| < l0); see
/// spring_force_jacobian_clamped(). Zero when |d| < spring_length_epsilon.
inline Eigen::Matrix3d spring_force_jacobian(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj,
                                             double k, double l0) {
  const Eigen::Vector3d d = xi - xj;
  const double length = d.norm();
  if (length < spring_length_epsilon) return Eigen::Matrix3d::Zero();
  const Eigen::Vector3d u = d / length;
  const Eigen::Matrix3d uut = u * u.transpose();
  return -k * ((1.0 - l0 / length) * (Eigen::Matrix3d::Identity() - uut) + uut);
}

/// Negative semidefinite approximation of spring_force_jacobian(), 3x3 (N/m):
/// -k [ max(0, 1 - l0/|d|) (I - u u^T) + u u^T ].
/// Equal to the exact Jacobian when the spring is stretched (|d| >= l0); under compression the
/// transverse term, whose negative coefficient makes the implicit system indefinite, is dropped
/// (the standard definiteness fix; Choi & Ko 2002 discuss the instability of compressed springs).
/// Used by the implicit integrator so that its matrix stays symmetric positive definite.
inline Eigen::Matrix3d spring_force_jacobian_clamped(const Eigen::Vector3d& xi,
                                                     const Eigen::Vector3d& xj, double k,
                                                     double l0) {
  const Eigen::Vector3d d = xi - xj;
  const double length = d.norm();
  if (length < spring_length_epsilon) return Eigen::Matrix3d::Zero();
  const Eigen::Vector3d u = d / length;
  const Eigen::Matrix3d uut = u * u.transpose();
  const double transverse = l0 < length ? 1.0 - l0 / length : 0.0;
  return -k * (transverse * (Eigen::Matrix3d::Identity() - uut) + uut);
}

/// Upper triangle of a spring's block of backward Euler's Hessian, k [t I + (1 - t) u u^T] +
/// c n n^T (N/m), for d = xi - xj: the clamped stiffness -spring_force_jacobian_clamped(), t =
/// max(0, 1 - l0/|d|), u = d/|d| (none when |d| < spring_length_epsilon), plus a viscous term c
/// (N/m) along the unit direction n. Six values computed directly, for Newton's Hessian.
inline SymmetricBlock spring_hessian_block(const Eigen::Vector3d& d, double k, double l0,
                                           const Eigen::Vector3d& n, double c) {
  const double length = d.norm();
  double along = 0.0, transverse = 0.0;  // k (1 - t) / |d|^2 and k t (N/m per m^2, N/m)
  if (length >= spring_length_epsilon) {
    const double t = l0 < length ? 1.0 - l0 / length : 0.0;
    along = k * (1.0 - t) / (length * length);
    transverse = k * t;
  }
  SymmetricBlock block;
  block[0] = along * d[0] * d[0] + c * n[0] * n[0] + transverse;
  block[1] = along * d[0] * d[1] + c * n[0] * n[1];
  block[2] = along * d[0] * d[2] + c * n[0] * n[2];
  block[3] = along * d[1] * d[1] + c * n[1] * n[1] + transverse;
  block[4] = along * d[1] * d[2] + c * n[1] * n[2];
  block[5] = along * d[2] * d[2] + c * n[2] * n[2] + transverse;
  return block;
}

/// Viscous force on i (N): f_i = -nu ((vi - vj) . u) u, u = (xi - xj) / |xi - xj|.
/// Source: course "Forces des ressorts" (viscosité, written there without the minus sign); it
/// damps the relative velocity along the spring only. Zero when |d| < spring_length_epsilon.
inline Eigen::Vector3d spring_damping_force(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj,
                                            const Eigen::Vector3d& vi, const Eigen::Vector3d& vj,
                                            double nu) {
  const Eigen::Vector3d d = xi - xj;
  const double length = d.norm();
  if (length < spring_length_epsilon) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d u = d / length;
  return (-nu * (vi - vj).dot(u)) * u;
}

/// Jacobian of the viscous force on i with respect to vi, 3x3 (N s/m): df_i/dvi = -nu u u^T
/// (symmetric negative semidefinite; df_i/dvj = -df_i/dvi). Source: Baraff & Witkin 1998
/// (damping forces). Its dependence on x, which is not symmetric, is left out of the
/// position Jacobian, as Baraff & Witkin do. Zero when |d| < spring_length_epsilon.
inline Eigen::Matrix3d spring_damping_force_jacobian(const Eigen::Vector3d& xi,
                                                     const Eigen::Vector3d& xj, double nu) {
  const Eigen::Vector3d d = xi - xj;
  const double length = d.norm();
  if (length < spring_length_epsilon) return Eigen::Matrix3d::Zero();
  const Eigen::Vector3d u = d / length;
  return -nu * u * u.transpose();
}

}  // namespace tissu
