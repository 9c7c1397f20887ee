#pragma once
/// \file
/// Parameters of a time step: the integrator, the time step and the environment's forces.

#include <Eigen/Core>

namespace tissu {

enum class Integrator {
  symplectic_euler,  ///< v += h a(x, v); x += h v (semi-implicit Euler)
  position_verlet,   ///< Stormer-Verlet in leapfrog form, second order (course, Algorithm 2)
  implicit_euler,    ///< one linearised backward-Euler step (Baraff & Witkin 1998)
};

/// Wind blowing on the cloth faces; gusts modulate the mean velocity.
struct Wind {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< mean wind velocity (m/s)
  double gust_amplitude =
      0.0;  ///< relative gust strength a: w(t) = velocity (1 + a g(t)), |g| <= 1
  double gust_frequency = 0.0;    ///< main gust frequency f (Hz)
  double air_density = 1.2;       ///< rho_air (kg/m^3)
  double drag_coefficient = 1.0;  ///< C_d of a flat plate facing the flow, dimensionless
};

/// Forces that come from outside the cloth.
struct Environment {
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};  ///< g (m/s^2)
  double air_damping = 0.0;                  ///< mass-proportional drag c: f_i = -c m_i v_i (1/s)
  Wind wind;
};

/// Linear solve of the implicit integrator.
struct ImplicitOptions {
  /// relative residual |b - A dv| / |b| of the conjugate gradient, dimensionless. 1e-5 leaves the
  /// curtain demo's energy unchanged to 1e-7 relative against 1e-8, in 40% less time.
  double cg_tolerance = 1e-5;
  int cg_max_iterations = 1000;  ///< a step whose solve has not converged by then is NotConverged
};

struct SolverParams {
  Integrator integrator = Integrator::implicit_euler;
  double time_step = 1e-3;  ///< h (s), one step; a frame is several steps
  Environment environment;
  ImplicitOptions implicit;
};

}  // namespace tissu
