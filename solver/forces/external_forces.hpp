#pragma once
/// \file
/// Forces from outside the cloth only: gravity, air damping and wind, without the springs.

#include <Eigen/Core>

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// External force f_ext (3#P, N) at positions x (3#P, m), velocities v (3#P, m/s), time t (s):
/// f_i = m_i g - c m_i v_i + 1/3 sum over triangles of i of the aerodynamic force,
/// i.e. accumulate_forces() without the spring terms (course, Algorithm 2: f_ext = f_g - v
/// f_damping plus the wind of aerodynamic_force.hpp). `triangle_forces` (3 x #T) is scratch.
/// Deterministic for any number of OpenMP threads.
void accumulate_external_forces(const SpringModel& model, const Environment& environment,
                                double time_s, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                Eigen::Matrix3Xd& triangle_forces, Eigen::VectorXd& force);

}  // namespace tissu
