#include "solver/integrators/implicit_euler.hpp"

#include <Eigen/IterativeLinearSolvers>

#include "solver/forces/accumulate_forces.hpp"
#include "solver/forces/spring_coupling.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

// per spring: the block -(h D + h^2 K) of A and the product K (v_i - v_j) of the right-hand side
void compute_spring_terms(const SpringModel& model, double h, const State& state,
                          ImplicitEulerWorkspace& workspace) {
  const int springs = model.spring_count();
  workspace.spring_blocks.resize(springs);
  workspace.spring_products.resize(3, springs);
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const int i = model.springs(s, 0);
    const int j = model.springs(s, 1);
    const auto xi = state.x.segment<3>(3 * i);
    const auto xj = state.x.segment<3>(3 * j);
    const Eigen::Matrix3d dfdx =
        spring_force_jacobian_clamped(xi, xj, model.stiffness[s], model.rest_length[s]);
    const Eigen::Matrix3d dfdv = spring_damping_force_jacobian(xi, xj, model.damping[s]);
    workspace.spring_blocks[s] = -(h * dfdv + (h * h) * dfdx);
    workspace.spring_products.col(s) =
        dfdx * (state.v.segment<3>(3 * i) - state.v.segment<3>(3 * j));
  }
}

// the couplings' part of the same two terms (spring_coupling.hpp): the geometric stiffness of
// their tensions per spring, and their cross term of df/dx v; their cross blocks of A are added
// once A is assembled
void add_coupling_terms(const SpringModel& model, double h, const State& state,
                        const Eigen::VectorXd& coupling_tension,
                        ImplicitEulerWorkspace& workspace) {
  const int springs = model.spring_count();
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const int i = model.springs(s, 0);
    const int j = model.springs(s, 1);
    const Eigen::Matrix3d dfdx = coupling_tension_jacobian(
        state.x.segment<3>(3 * i), state.x.segment<3>(3 * j), coupling_tension[s], true);
    workspace.spring_blocks[s] -= (h * h) * dfdx;
    workspace.spring_products.col(s) +=
        dfdx * (state.v.segment<3>(3 * i) - state.v.segment<3>(3 * j));
  }
  add_coupling_velocity_products(model, state.x, state.v, workspace.spring_products);
}

// b = S h (f0 + h df/dx v0), gathered per particle in incidence order
void compute_rhs(const SpringModel& model, double h, const Eigen::VectorXd& force,
                 ImplicitEulerWorkspace& workspace) {
  const int particles = model.particle_count();
  const ParticleSpringIncidence& incidence = model.incidence;
  workspace.rhs.resize(3 * particles);
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.inverse_mass[p] == 0.0) {
      workspace.rhs.segment<3>(3 * p).setZero();
      continue;
    }
    Eigen::Vector3d stiffness_times_velocity = Eigen::Vector3d::Zero();
    for (int e = incidence.offsets[p]; e < incidence.offsets[p + 1]; ++e) {
      const auto product = workspace.spring_products.col(incidence.springs[e]);
      if (incidence.first_end[e]) {
        stiffness_times_velocity += product;
      } else {
        stiffness_times_velocity -= product;
      }
    }
    workspace.rhs.segment<3>(3 * p) = h * (force.segment<3>(3 * p) + h * stiffness_times_velocity);
  }
}

}  // namespace

StepStatus implicit_euler_step(const SpringModel& model, const SolverParams& params, State& state,
                               StepWorkspace& workspace) {
  const double h = params.time_step;
  const int particles = model.particle_count();
  ImplicitEulerWorkspace& implicit = workspace.implicit;

  accumulate_forces(model, params.environment, state.time, state.x, state.v, workspace.forces,
                    workspace.force);
  compute_spring_terms(model, h, state, implicit);
  const bool coupled = model.couplings.rows() > 0;
  if (coupled) add_coupling_terms(model, h, state, workspace.forces.coupling_tension, implicit);
  compute_rhs(model, h, workspace.force, implicit);
  if (!implicit.rhs.allFinite()) return StepStatus::non_finite;

  // A = M (1 + h c) - h df/dv - h^2 df/dx, filtered on pinned particles
  implicit.diagonal = (1.0 + h * params.environment.air_damping) * model.mass;
  update_spring_block_pattern(model, implicit.pattern);
  assemble_spring_block_matrix(model, implicit.pattern, implicit.spring_blocks, implicit.diagonal,
                               true, implicit.system_matrix);
  if (coupled) {
    add_coupling_jacobian_blocks(model, implicit.pattern, state.x, -h * h, true,
                                 implicit.system_matrix);
  }

  Eigen::ConjugateGradient<Eigen::SparseMatrix<double, Eigen::RowMajor>,
                           Eigen::Lower | Eigen::Upper>
      cg;
  cg.setTolerance(params.implicit.cg_tolerance);
  cg.setMaxIterations(params.implicit.cg_max_iterations);
  cg.compute(implicit.system_matrix);
  if (implicit.warm_start_model != model.identity || !implicit.velocity_change.allFinite()) {
    implicit.velocity_change.setZero(3 * particles);  // the last solve was for another model
    implicit.warm_start_model = model.identity;
  }
  implicit.velocity_change = cg.solveWithGuess(implicit.rhs, implicit.velocity_change);
  implicit.cg_iterations = static_cast<int>(cg.iterations());
  const StepStatus status =
      cg.info() == Eigen::Success ? StepStatus::ok : StepStatus::not_converged;

#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.inverse_mass[p] != 0.0) {
      state.v.segment<3>(3 * p) += implicit.velocity_change.segment<3>(3 * p);
    }
    state.x.segment<3>(3 * p) += h * state.v.segment<3>(3 * p);
  }
  return status;
}

}  // namespace tissu
