#include "solver/integrators/position_verlet.hpp"

#include "solver/forces/accumulate_forces.hpp"
#include "solver/parallel.hpp"

namespace tissu {

StepStatus position_verlet_step(const SpringModel& model, const SolverParams& params, State& state,
                                StepWorkspace& workspace) {
  const double h = params.time_step;
  const int particles = model.particle_count();
  state.x += (0.5 * h) * state.v;
  accumulate_forces(model, params.environment, state.time + 0.5 * h, state.x, state.v,
                    workspace.forces, workspace.force);
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    state.v.segment<3>(3 * p) += (h * model.inverse_mass[p]) * workspace.force.segment<3>(3 * p);
    state.x.segment<3>(3 * p) += (0.5 * h) * state.v.segment<3>(3 * p);
  }
  return StepStatus::ok;
}

}  // namespace tissu
