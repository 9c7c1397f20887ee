#pragma once
/// \file
/// The force the pins exert on the cloth, for statistics: what a user checks first of a hanging
/// cloth (at rest it equals the weight the pins carry).

#include <Eigen/Core>

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Sum over pinned particles i of R_i = -f_i (N), f_i the total force accumulate_forces() gives
/// (springs, couplings, gravity, air damping, wind) at `state`: a pinned particle moves as its
/// handle prescribes, at constant velocity, so Newton's second law m_i a_i = f_i + R_i with
/// a_i = 0 leaves R_i = -f_i. Zero when nothing is pinned. Obstacle contacts are not in f_i:
/// obstacles act on free particles.
Eigen::Vector3d pin_reaction_force(const SpringModel& model, const Environment& environment,
                                   const State& state);

}  // namespace tissu
