#pragma once
/// \file
/// A speed no particle of a scene can legitimately reach, to tell a numerical blow-up from motion
/// at the step where it starts (docs/scenario.md, "When a run diverges").
///
/// An explicit integrator stepping springs too stiff for its step amplifies their fastest mode by
/// about (h omega)^2 per step: speeds leap by orders of magnitude within a step or two, long
/// before they overflow to inf. What a scene can make a particle do has a bound instead: from
/// rest, gravity alone gives |g| t; the cloth is driven no faster than its fastest handle,
/// obstacle or wind; a spring stretched by d that lets go gives its lighter end (mass m) at most
/// |d| sqrt(k / m), its energy 1/2 k d^2 all given to that end (the same e c is the particle speed
/// behind a release wave in a bar at strain e, of wave speed c = l0 sqrt(k / m)), with the
/// stretches of the start (a gathered or pre-stretched cloth) and of the moments the cloth tears
/// or is cut. The limit is `margin` times their sum. CGAL-free.

#include <optional>

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// The ingredients of a run's speed limit; see speed_limit_m_per_s().
struct SpeedLimit {
  /// how far above the scene's bound a speed must be to be a blow-up, dimensionless, > 0. 10:
  /// the shipped scenarios stay below 0.12 of the limit (docs/scenario.md), an unstable explicit
  /// step multiplies speeds by (h omega)^2, 1e2 to 1e5 on the scenes that blow up.
  double margin = 10.0;
  double start_time_s = 0.0;           ///< time at which the run starts (s)
  double initial_speed_m_per_s = 0.0;  ///< fastest particle at the start, pinned ones too
  /// fastest point of an obstacle over its whole motion: of the surface, for a rotating one (of
  /// a rotating plane, as far from its pivot as the cloth at the start)
  double obstacle_speed_m_per_s = 0.0;
  double handle_speed_m_per_s = 0.0;  ///< fastest keyframed pin handle (set by the caller)
  double wind_speed_m_per_s = 0.0;    ///< strongest wind, |w| (1 + |gust amplitude|)
  double gravity_m_per_s2 = 0.0;      ///< |g|
  /// fastest a spring can have let go of an end so far, spring_release_speed_m_per_s() at the
  /// start and after every tear or cut (widen_for_release())
  double release_speed_m_per_s = 0.0;
};

/// The limit of a run starting from `state` with `params`: obstacles, wind and gravity from
/// params, the initial speeds and stretches from the state.
SpeedLimit speed_limit_at_start(const SpringModel& model, const SolverParams& params,
                                const State& state);

/// Distance from `point` to the farthest particle of `state` (m): how far a rotation about
/// `point` can reach the cloth.
double farthest_particle_m(const State& state, const Eigen::Vector3d& point);

/// max over springs s of |l_s - l0_s| sqrt(k_s / min(m_i, m_j)) in `state` (m/s); 0 without
/// springs.
double spring_release_speed_m_per_s(const SpringModel& model, const State& state);

/// Raises limit.release_speed_m_per_s to the springs' release speed in `state`: call after the
/// cloth tore or was cut, with the torn model and the state the tear saw, so that the crack's
/// lips may spring back.
void widen_for_release(SpeedLimit& limit, const SpringModel& model, const State& state);

/// The limit at time `time_s`: margin (v_0 + v_obstacle + v_wind + |g| (t - t_0) + v_release)
/// (m/s).
double speed_limit_m_per_s(const SpeedLimit& limit, double time_s);

/// A free particle over the limit.
struct Overspeed {
  int particle = 0;            ///< the fastest free particle
  double speed_m_per_s = 0.0;  ///< its speed
  double limit_m_per_s = 0.0;  ///< the limit it exceeds
};

/// The fastest free (not pinned) particle of `state` if its speed exceeds the limit at
/// state.time (a NaN speed does), else nothing. Pinned particles move as prescribed and are not
/// checked.
std::optional<Overspeed> find_overspeed(const SpeedLimit& limit, const SpringModel& model,
                                        const State& state);

}  // namespace tissu
