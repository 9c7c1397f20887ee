#pragma once
/// \file
/// Position (Stormer-)Verlet integrator in leapfrog form.

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"
#include "solver/step_workspace.hpp"

namespace tissu {

/// One step of position Verlet (drift, kick, drift), second order, explicit, symplectic:
/// x_half = x + h/2 v;  v(t+h) = v + h M^-1 f(x_half, v, t + h/2);  x(t+h) = x_half + h/2 v(t+h).
/// Without velocity-dependent forces this is the Stormer-Verlet scheme of the course
/// (Algorithm 2, x(t+h) = 2 x(t) - x(t-h) + h^2 a) written with velocities, which keeps v at hand
/// for damping and for pinned particles. Source: Hairer, Lubich & Wanner 2003, "Geometric
/// numerical integration illustrated by the Stormer-Verlet method". Damping and wind use the
/// velocity at the start of the step (explicit). Pinned particles (inverse_mass 0) keep their
/// velocity and move with it. Does not advance state.time (step() does). Always ok.
StepStatus position_verlet_step(const SpringModel& model, const SolverParams& params, State& state,
                                StepWorkspace& workspace);

}  // namespace tissu
