#include "solver/integrators/projective_dynamics.hpp"

#include <stdexcept>

#include "solver/forces/external_forces.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/integrators/incremental_potential.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

// y = x + h v + h^2 f_ext / m and the first iterate p = x + h v; pinned: y = p = x + h v
void predict(const SpringModel& model, double h, const State& state,
             ProjectiveDynamicsWorkspace& pd) {
  const int particles = model.particle_count();
  pd.inertial.resize(3 * particles);
  pd.positions.resize(3 * particles);
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    const Eigen::Vector3d moved = state.x.segment<3>(3 * p) + h * state.v.segment<3>(3 * p);
    pd.positions.segment<3>(3 * p) = moved;
    pd.inertial.segment<3>(3 * p) =
        moved + (h * h * model.inverse_mass[p]) * pd.external_force.segment<3>(3 * p);
  }
}

// max_i |p_i - last_i| <= tolerance max_i |p_i - x_i|
bool has_converged(const Eigen::VectorXd& p, const Eigen::VectorXd& last, const Eigen::VectorXd& x,
                   double tolerance) {
  const double change = (p - last).lpNorm<Eigen::Infinity>();
  const double displacement = (p - x).lpNorm<Eigen::Infinity>();
  return change <= tolerance * displacement;
}

void check_options(const ProjectiveDynamicsOptions& options) {
  if (options.iterations < 1 || options.linear_iterations < 1 || !(options.tolerance >= 0.0) ||
      !(options.chebyshev_spectral_radius >= 0.0 && options.chebyshev_spectral_radius < 1.0) ||
      !(options.chebyshev_relaxation > 0.0 && options.chebyshev_relaxation <= 1.0) ||
      !(options.max_estimated_error >= 0.0)) {
    throw std::invalid_argument(
        "projective_dynamics_step: expected pd.iterations >= 1, pd.linear_iterations >= 1, "
        "pd.tolerance >= 0, pd.chebyshev_spectral_radius in [0, 1), pd.chebyshev_relaxation "
        "in (0, 1] and pd.max_estimated_error >= 0");
  }
}

// relative_correction() of the change that solving the last global step exactly would still
// make to the iterate (the error the iterative global solver left in it), against what the
// cloth's own forces move it in the step, max_i |p_i - y_i| from the inertial prediction y, or,
// for a cloth that falls unstretched, 1 % of what gravity moves a particle in a step. Not against
// the step's displacement from x: that is mostly h v, which the solve does not decide, and a
// moving oscillator at a small step hid an error of 4 % of its spring's pull (a 1.9 % longer
// period) behind it. Needs the direct solver's factorisation (made once per model and h).
constexpr double rest_fraction = 0.01;

double estimated_step_error(const SpringModel& model, double h, ProjectiveDynamicsWorkspace& pd) {
  pd.correction = pd.positions;  // pinned entries: their prescribed positions, read by the solve
  if (!pd.direct.solve(pd.system, pd.rhs, pd.correction)) return 0.0;
  pd.correction -= pd.positions;
  return relative_correction(model, h, pd.correction, pd.positions, pd.inertial, pd.external_force,
                             rest_fraction);
}

}  // namespace

void pd_local_step(const SpringModel& model, const Eigen::VectorXd& p, const Eigen::VectorXd& x,
                   Eigen::Matrix3Xd& projections) {
  const int springs = model.spring_count();
  projections.resize(3, springs);
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const int i = model.springs(s, 0);
    const int j = model.springs(s, 1);
    Eigen::Vector3d d = p.segment<3>(3 * i) - p.segment<3>(3 * j);
    double length = d.norm();
    if (length < spring_length_epsilon) {
      d = x.segment<3>(3 * i) - x.segment<3>(3 * j);
      length = d.norm();
    }
    if (length < spring_length_epsilon) {
      projections.col(s).setZero();
    } else {
      projections.col(s) = (model.rest_length[s] / length) * d;
    }
  }
}

void pd_global_rhs(const SpringModel& model, const PdSystem& system, const Eigen::VectorXd& y,
                   const Eigen::Matrix3Xd& projections, Eigen::VectorXd& rhs) {
  const int particles = model.particle_count();
  const ParticleSpringIncidence& incidence = model.incidence;
  rhs.resize(3 * particles);
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    Eigen::Vector3d c = system.inertia[p] * y.segment<3>(3 * p);
    for (int e = incidence.offsets[p]; e < incidence.offsets[p + 1]; ++e) {
      const auto d = projections.col(incidence.springs[e]);
      if (incidence.first_end[e]) {
        c += system.weights[e] * d;
      } else {
        c -= system.weights[e] * d;
      }
    }
    rhs.segment<3>(3 * p) = c;
  }
}

StepStatus projective_dynamics_step(const SpringModel& model, const SolverParams& params,
                                    State& state, StepWorkspace& workspace) {
  if (model.couplings.rows() > 0) {
    throw std::invalid_argument(
        "projective_dynamics_step: the model has spring couplings, which Projective Dynamics "
        "cannot project; step it with implicit_euler, symplectic_euler or position_verlet");
  }
  const double h = params.time_step;
  const ProjectiveDynamicsOptions& options = params.pd;
  const int particles = model.particle_count();
  ProjectiveDynamicsWorkspace& pd = workspace.pd;
  check_options(options);

  accumulate_external_forces(model, params.environment, state.time, state.x, state.v,
                             pd.triangle_forces, pd.external_force);
  predict(model, h, state, pd);
  if (!pd.inertial.allFinite()) return StepStatus::non_finite;
  update_pd_system(model, h, pd.system);
  const bool direct = options.global_solver == PdGlobalSolver::direct;
  if (direct && !pd.direct.factorize(pd.system)) return StepStatus::non_finite;
  reset_pd_iterative_state(pd.positions, pd.iterative);

  const bool check = options.tolerance > 0.0;
  bool converged = !check;
  pd.iterations = 0;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    if (check) pd.last_positions = pd.positions;
    pd_local_step(model, pd.positions, state.x, pd.projections);
    pd_global_rhs(model, pd.system, pd.inertial, pd.projections, pd.rhs);
    if (direct) {
      pd.direct.solve(pd.system, pd.rhs, pd.positions);
    } else {
      pd_iterative_solve(pd.system, options, pd.rhs, options.linear_iterations, pd.positions,
                         pd.iterative);
    }
    ++pd.iterations;
    if (check && has_converged(pd.positions, pd.last_positions, state.x, options.tolerance)) {
      converged = true;
      break;
    }
  }
  pd.estimated_error = 0.0;
  if (!direct && options.max_estimated_error > 0.0) {  // the direct solver's global steps are exact
    pd.estimated_error = estimated_step_error(model, h, pd);
    if (!(pd.estimated_error <= options.max_estimated_error)) converged = false;
  }

  const double inverse_h = 1.0 / h;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.inverse_mass[p] == 0.0) {
      state.x.segment<3>(3 * p) += h * state.v.segment<3>(3 * p);
    } else {
      state.v.segment<3>(3 * p) =
          inverse_h * (pd.positions.segment<3>(3 * p) - state.x.segment<3>(3 * p));
      state.x.segment<3>(3 * p) = pd.positions.segment<3>(3 * p);
    }
  }
  return converged ? StepStatus::ok : StepStatus::not_converged;
}

}  // namespace tissu
