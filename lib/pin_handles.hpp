#pragma once
/// \file
/// The handles of a run: pins entries that move their particles along keyframes, take hold of
/// them and let them go. Includes CGAL: include it from lib/ sources only.

#include <vector>

#include "topology/compile.hpp"
#include "topology/pin_selection.hpp"

namespace tissu {

/// Moves and schedules the pinned particles of a run, entry by entry of the scenario's "pins"
/// (Particle::pin_group). A pinned particle moves by x += h v in every integrator; before each
/// step this gives the particles of a keyframed handle the velocity that lands them where the
/// handle carries them, v = (P(t + h) P(t)^-1 x - x) / h with P the handle's pose (RigidMotion):
/// they follow the keys to round-off, and a particle a split adds on a handle's edge follows too.
/// Handles without keyframes keep the constant velocity they were given.
class PinHandles {
 public:
  explicit PinHandles(const std::vector<PinSelector>& pins) : m_pins(pins) {}

  /// Before the step of `time_step_s` from cloth.state.time: lets go of the particles of every
  /// handle whose release_at_s is due (they keep their velocity), takes hold of those whose
  /// attach_at_s is due (they take the handle's velocity) — due at the step starting nearest to
  /// the time — recompiling the cloth when either happened, then sets the keyframed handles'
  /// velocities.
  void before_step(ClothComplex& lcc, CompiledCloth& cloth, double time_step_s);

  /// An upper bound on how fast a handle moves its particles (m/s), for the run's speed limit:
  /// a rotating handle's particles as far from its pivot as the farthest particle of `state`.
  double fastest_speed_m_per_s(const State& state) const;

 private:
  const std::vector<PinSelector>& m_pins;
  double m_done_until_s = -1.0;  ///< attach and release times at or before this have been applied
};

}  // namespace tissu
