#include "solver/pin_reaction.hpp"

#include <algorithm>

#include "solver/forces/accumulate_forces.hpp"

namespace tissu {

Eigen::Vector3d pin_reaction_force(const SpringModel& model, const Environment& environment,
                                   const State& state) {
  Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
  if (std::find(model.pinned.begin(), model.pinned.end(), 1) == model.pinned.end()) return reaction;
  ForceWorkspace workspace;
  Eigen::VectorXd force;
  accumulate_forces(model, environment, state.time, state.x, state.v, workspace, force);
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned[i]) reaction -= force.segment<3>(3 * i);
  }
  return reaction;
}

}  // namespace tissu
