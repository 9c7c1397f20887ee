#pragma once
/// \file
/// Wind and air drag on the surface triangles of the cloth.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Deterministic gust signal, dimensionless, |g| <= 1:
/// g(t) = 0.7 sin(2 pi f t) + 0.3 sin(2 pi 2.3 f t + 1.3), f in Hz, t in s. Two incommensurate
/// sines so the gusts do not look periodic, yet every run (and every thread count) sees the same.
double gust_signal(double frequency_hz, double time_s);

/// Wind velocity at time t (m/s): w(t) = velocity (1 + a g(t)), a = wind.gust_amplitude.
Eigen::Vector3d wind_velocity(const Wind& wind, double time_s);

/// Aerodynamic force on one triangle (a, b, c) (N), to be shared equally by its three vertices:
/// f = 1/2 rho C_d A (v_rel . n) |v_rel . n| n, with v_rel = w - (va + vb + vc) / 3 the air
/// velocity relative to the triangle (m/s), n the unit normal of (b - a) x (c - a) and A its area
/// (m^2). Source: Rayleigh's quadratic drag F = 1/2 rho C_d A |v|^2 applied to the normal
/// component of the relative flow, as for a flat plate (the tangential skin friction is
/// neglected). Zero for a degenerate (zero-area) triangle.
Eigen::Vector3d triangle_aerodynamic_force(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                           const Eigen::Vector3d& xc, const Eigen::Vector3d& va,
                                           const Eigen::Vector3d& vb, const Eigen::Vector3d& vc,
                                           const Eigen::Vector3d& wind_velocity_mps,
                                           double air_density_kgpm3, double drag_coefficient);

/// Adds the aerodynamic force of every triangle of model.triangles to `force` (3#P, N), one third
/// to each vertex. Triangle forces are computed in parallel into `triangle_forces` (3 x #T, N,
/// resized as needed) and then added serially in triangle order, so that the result is the same
/// for any number of OpenMP threads. Does nothing when rho C_d = 0. x, v: 3#P (m, m/s).
void add_aerodynamic_forces(const SpringModel& model, const Wind& wind, double time_s,
                            const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                            Eigen::Matrix3Xd& triangle_forces, Eigen::VectorXd& force);

}  // namespace tissu
