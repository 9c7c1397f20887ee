#pragma once
/// \file
/// Total force on every particle: springs, gravity, air damping and wind.

#include <Eigen/Core>

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Scratch buffers of accumulate_forces(), kept by the caller so that a step allocates nothing once
/// the sizes are known. Contents are meaningless between calls.
struct ForceWorkspace {
  Eigen::Matrix3Xd spring_forces;    ///< 3 x #S elastic + viscous force on springs(s, 0) (N)
  Eigen::VectorXd spring_stretch;    ///< #S |d| - l0 (m), with couplings only
  Eigen::VectorXd coupling_tension;  ///< #S tension the couplings add to each spring (N)
  Eigen::Matrix3Xd triangle_forces;  ///< 3 x #T aerodynamic force on each vertex of a triangle (N)
};

/// Total force f (3#P, N) at positions x (3#P, m), velocities v (3#P, m/s) and time t (s):
/// f_i = sum over springs (i, j) of [ -k (|d| - l0) u - nu ((vi - vj) . u) u ]   (springs)
///       - sum over springs (i, j) of T_s u                  (couplings, spring_coupling.hpp)
///       + m_i g                                                              (gravity)
///       - c m_i v_i                                                          (air damping)
///       + 1/3 sum over triangles of i of the aerodynamic force               (wind)
/// with d = xi - xj, u = d / |d|. Source: course "Forces des ressorts" (see spring_force.hpp for
/// the sign convention); wind in aerodynamic_force.hpp.
/// Deterministic for any number of OpenMP threads: spring forces are computed in parallel into a
/// per-spring buffer, then each particle gathers its springs in the fixed order of
/// model.incidence. Pinned particles get their force too (integrators ignore it).
void accumulate_forces(const SpringModel& model, const Environment& environment, double time_s,
                       const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                       ForceWorkspace& workspace, Eigen::VectorXd& force);

}  // namespace tissu
