#pragma once
/// \file
/// Provot's deformation constraint (X. Provot, "Deformation constraints in a mass-spring model
/// to describe rigid cloth behavior", Graphics Interface 1995): after a step, a structural spring
/// stretched beyond (1 + limit) times its rest length is brought back to it by moving its two
/// ends towards each other, in inverse proportion to their masses (a pinned end stays), and their
/// velocities take the same change over the step. Real fabric barely stretches; a mass-spring
/// cloth stiff enough not to would need steps too small, so its few overstretched springs (a
/// corner carrying the cloth, a sleeve dragged by a limb) are corrected directly.

#include "solver/spring_model.hpp"

namespace tissu {

/// Applies the constraint to `state` (positions in m, velocities in m/s) for steps of
/// `time_step_s`: at most `sweeps` Gauss-Seidel sweeps over the structural springs, alternately
/// in their order and in reverse (the same result on any thread count), stopping after one that
/// corrected nothing; each correction leaves its spring exactly at the limit, but later ones may
/// stretch it again, so a cloth under load ends near the limit rather than within it. A limit of
/// 0 does nothing. Each correction moves the two ends by equal and opposite momenta, so
/// the cloth's momentum is kept. Returns how many springs the first sweep corrected.
int limit_strain(const SpringModel& model, double limit, double time_step_s, State& state,
                 int sweeps = 16);

}  // namespace tissu
