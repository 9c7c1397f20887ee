#include "solver/integrators/symplectic_euler.hpp"

#include "solver/forces/accumulate_forces.hpp"
#include "solver/parallel.hpp"

namespace tissu {

StepStatus symplectic_euler_step(const SpringModel& model, const SolverParams& params, State& state,
                                 StepWorkspace& workspace) {
  const double h = params.time_step;
  accumulate_forces(model, params.environment, state.time, state.x, state.v, workspace.forces,
                    workspace.force);
  const int particles = model.particle_count();
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    state.v.segment<3>(3 * p) += (h * model.inverse_mass[p]) * workspace.force.segment<3>(3 * p);
    state.x.segment<3>(3 * p) += h * state.v.segment<3>(3 * p);
  }
  return StepStatus::ok;
}

}  // namespace tissu
