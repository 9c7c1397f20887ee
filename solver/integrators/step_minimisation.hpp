#pragma once
/// \file
/// What the minimisers of backward Euler's incremental potential (Newton, quasi-Newton) share:
/// the start of a step (its potential, first iterate and the PD matrix) and its end.

#include <Eigen/Core>

#include "solver/integrators/incremental_potential.hpp"
#include "solver/integrators/minimisation_workspace.hpp"
#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"

namespace tissu {

/// Starts a step: f_ext (gravity and wind; air damping is left to the potential, implicit), y,
/// x = x_0 = x_n + h v_n, with `use_pd_matrix` the PD matrix for this model and h and its
/// factorisation (a Newton step preconditioned by multigrid needs neither), the potential's start
/// directions and obstacle contacts (with SolverParams::obstacle_penalty; `obstacle_distances`, if
/// given and prepared for this step, skips the mesh queries it can answer; with
/// SolverParams::friction_in_step their friction from `lagged_normal_impulse`, or estimated
/// without it, lag_contact_friction()), and E(x_0) with its gradient. Fills `potential` (which
/// points into `workspace` and `state`). False when something is not finite (or the PD matrix
/// cannot be factorised): the step is then non_finite.
bool start_step_minimisation(const SpringModel& model, const SolverParams& params,
                             const State& state, MinimisationWorkspace& workspace,
                             ObstacleDistanceCache* obstacle_distances,
                             const Eigen::MatrixXd* lagged_normal_impulse, StepPotential& potential,
                             double& energy_j, bool use_pd_matrix = true);

/// Ends a step at the iterate x (3#P, m): v = (x - x_n)/h for the free particles, then x (pinned
/// particles keep their velocity, x holds their x_0). Returns non_finite, leaving the state as it
/// was, when x is not finite; otherwise ok if the minimiser `converged`, else not_converged.
StepStatus finish_step_minimisation(const SpringModel& model, double time_step_s,
                                    const Eigen::VectorXd& x, bool converged, State& state);

}  // namespace tissu
