#pragma once
/// \file
/// Symplectic (semi-implicit) Euler integrator.

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"
#include "solver/step_workspace.hpp"

namespace tissu {

/// One step of symplectic Euler, first order, explicit:
/// v(t+h) = v + h M^-1 f(x, v, t);  x(t+h) = x + h v(t+h).
/// Source: course "Boucle de simulation" (forces, accelerations, velocities, then positions);
/// Hairer, Lubich & Wanner 2003 for its symplecticity. Pinned particles (inverse_mass 0) keep
/// their velocity and move with it. Does not advance state.time (step() does). Always ok.
StepStatus symplectic_euler_step(const SpringModel& model, const SolverParams& params, State& state,
                                 StepWorkspace& workspace);

}  // namespace tissu
