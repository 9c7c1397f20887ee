#include "solver/step.hpp"

#include <stdexcept>
#include <string>

#include "solver/collision/obstacle_contacts.hpp"
#include "solver/collision/self_collision.hpp"
#include "solver/integrators/implicit_euler.hpp"
#include "solver/integrators/newton.hpp"
#include "solver/integrators/position_verlet.hpp"
#include "solver/integrators/projective_dynamics.hpp"
#include "solver/integrators/quasi_newton.hpp"
#include "solver/integrators/symplectic_euler.hpp"
#include "solver/strain_limit.hpp"

namespace tissu {
namespace {

void check_state_size(const SpringModel& model, const State& state) {
  const Eigen::Index dofs = 3 * static_cast<Eigen::Index>(model.particle_count());
  if (state.x.size() != dofs || state.v.size() != dofs) {
    throw std::invalid_argument("step: state has " + std::to_string(state.x.size()) +
                                " positions and " + std::to_string(state.v.size()) +
                                " velocities, expected 3#P = " + std::to_string(dofs) + " each");
  }
  if (model.identity == 0 || model.inverse_mass.size() != model.mass.size() ||
      model.incidence.offsets.size() != static_cast<std::size_t>(model.particle_count()) + 1) {
    throw std::invalid_argument("step: model is not finalized, call finalize_model() first");
  }
}

/// The obstacle contacts that the step's minimiser held inside the step, if it did.
const std::vector<ContactPlane>* minimised_contacts(const SolverParams& params,
                                                    const StepWorkspace& workspace) {
  if (params.integrator == Integrator::newton) return &workspace.newton.common.contacts;
  if (params.integrator == Integrator::quasi_newton) return &workspace.quasi_newton.common.contacts;
  return nullptr;
}

/// The particles whose position differs between `before` and `after` (3#P each), in order.
void moved_particles(const Eigen::VectorXd& before, const Eigen::VectorXd& after,
                     std::vector<int>& moved) {
  moved.clear();
  for (Eigen::Index p = 0; p < before.size() / 3; ++p) {
    if (before.segment<3>(3 * p) != after.segment<3>(3 * p)) moved.push_back(static_cast<int>(p));
  }
}

}  // namespace

const char* to_string(Integrator integrator) {
  switch (integrator) {
    case Integrator::symplectic_euler:
      return "symplectic_euler";
    case Integrator::position_verlet:
      return "position_verlet";
    case Integrator::implicit_euler:
      return "implicit_euler";
    case Integrator::projective_dynamics:
      return "projective_dynamics";
    case Integrator::newton:
      return "newton";
    case Integrator::quasi_newton:
      return "quasi_newton";
  }
  return "unknown";
}

const char* to_string(PdGlobalSolver solver) {
  switch (solver) {
    case PdGlobalSolver::direct:
      return "direct";
    case PdGlobalSolver::jacobi:
      return "jacobi";
    case PdGlobalSolver::chebyshev:
      return "chebyshev";
    case PdGlobalSolver::gauss_seidel:
      return "gauss_seidel";
    case PdGlobalSolver::colored_gauss_seidel:
      return "colored_gauss_seidel";
    case PdGlobalSolver::block_gauss_seidel:
      return "block_gauss_seidel";
  }
  return "unknown";
}

const char* to_string(NewtonPreconditioner preconditioner) {
  switch (preconditioner) {
    case NewtonPreconditioner::multigrid:
      return "multigrid";
    case NewtonPreconditioner::pd_matrix:
      return "pd_matrix";
  }
  return "unknown";
}

const char* to_string(QuasiNewtonInitialHessian initial_hessian) {
  switch (initial_hessian) {
    case QuasiNewtonInitialHessian::pd_matrix:
      return "pd_matrix";
    case QuasiNewtonInitialHessian::pd_multigrid:
      return "pd_multigrid";
  }
  return "unknown";
}

const char* to_string(StepStatus status) {
  switch (status) {
    case StepStatus::ok:
      return "ok";
    case StepStatus::non_finite:
      return "non_finite";
    case StepStatus::not_converged:
      return "not_converged";
  }
  return "unknown";
}

StepStatus step(const SpringModel& model, const SolverParams& params, State& state) {
  StepWorkspace workspace;
  return step(model, params, state, workspace);
}

StepStatus step(const SpringModel& model, const SolverParams& params, State& state,
                StepWorkspace& workspace) {
  check_state_size(model, state);
  if (!params.obstacles.empty() || params.self_collision.enabled) workspace.step_start_x = state.x;
  if (!params.obstacles.empty()) workspace.obstacle_distances.prepare(model, params.obstacles);
  StepStatus status = StepStatus::ok;
  switch (params.integrator) {
    case Integrator::symplectic_euler:
      status = symplectic_euler_step(model, params, state, workspace);
      break;
    case Integrator::position_verlet:
      status = position_verlet_step(model, params, state, workspace);
      break;
    case Integrator::implicit_euler:
      status = implicit_euler_step(model, params, state, workspace);
      break;
    case Integrator::projective_dynamics:
      status = projective_dynamics_step(model, params, state, workspace);
      break;
    case Integrator::newton:
      status = newton_step(model, params, state, workspace);
      break;
    case Integrator::quasi_newton:
      status = quasi_newton_step(model, params, state, workspace);
      break;
  }
  const bool finite =
      status != StepStatus::non_finite && state.x.allFinite() && state.v.allFinite();
  workspace.strain_limited = 0;
  if (finite) {  // a NaN would leave the hash cells of self-collision undefined
    // obstacles first: a particle an obstacle holds is then immovable for the cloth's own contacts
    const double end_time_s = state.time + params.time_step;
    const std::vector<ContactPlane>* held = minimised_contacts(params, workspace);
    if (held != nullptr && !held->empty()) {  // reuses the buffers: no allocation per step
      contact_normal_impulses(model, *held, static_cast<int>(params.obstacles.size()),
                              params.time_step, state.x, workspace.obstacle_penalty_impulse);
      if (params.friction_in_step) {
        workspace.obstacle_impulse_after_step = workspace.obstacle_penalty_impulse;
        remove_friction_given_in_step(*held, state.x, workspace.obstacle_impulse_after_step);
      }
    } else {
      workspace.obstacle_penalty_impulse.resize(0, 0);
      workspace.obstacle_impulse_after_step.resize(0, 0);
    }
    workspace.obstacle_penalty_impulse_model = model.identity;  // the next step's lagged friction
    // without friction in the step, friction after it has the whole penalty impulse: no copy
    const Eigen::MatrixXd& impulse_after_step = params.friction_in_step
                                                    ? workspace.obstacle_impulse_after_step
                                                    : workspace.obstacle_penalty_impulse;
    workspace.obstacle_contacts = resolve_obstacle_contacts(
        model, params.obstacles, params.time_step, end_time_s, workspace.step_start_x, state,
        workspace.obstacle_holding_normal, impulse_after_step, &workspace.obstacle_distances);
    const bool both = params.self_collision.enabled && !params.obstacles.empty();
    if (both) workspace.before_self_collision_x = state.x;
    workspace.self_collision = resolve_self_collisions(
        model, params.self_collision, params.time_step, workspace.step_start_x,
        workspace.obstacle_holding_normal, workspace.self_collision_pairs, state);
    // a layer pushed by another must not enter an obstacle: obstacles have the last word
    if (both) {
      moved_particles(workspace.before_self_collision_x, state.x,
                      workspace.moved_by_self_collision);
      resolve_obstacle_contacts_of(workspace.moved_by_self_collision, params.obstacles,
                                   params.time_step, end_time_s, workspace.step_start_x, state,
                                   &workspace.obstacle_distances);
    }
    // last: a contact's friction holding a particle would otherwise undo the correction at every
    // step (the T-shirt's sleeves, docs/benchmarks.md); what it moves into an obstacle, by a
    // fraction of an edge, the next step's contacts push out
    workspace.strain_limited = limit_strain(model, params.strain_limit, params.time_step, state);
  }
  state.time += params.time_step;
  if (!finite || !state.x.allFinite() || !state.v.allFinite()) return StepStatus::non_finite;
  return status;
}

int last_step_iterations(const SolverParams& params, const StepWorkspace& workspace) {
  switch (params.integrator) {
    case Integrator::implicit_euler:
      return workspace.implicit.cg_iterations;
    case Integrator::projective_dynamics:
      return workspace.pd.iterations;
    case Integrator::newton:
      return workspace.newton.iterations;
    case Integrator::quasi_newton:
      return workspace.quasi_newton.iterations + workspace.quasi_newton.newton_iterations;
    case Integrator::symplectic_euler:
    case Integrator::position_verlet:
      return 0;
  }
  return 0;
}

}  // namespace tissu
