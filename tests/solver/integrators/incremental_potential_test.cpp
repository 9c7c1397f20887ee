// Backward Euler's incremental potential: each spring's energy and force by the formula, on every
// kernel the processor can run, and the potential's gradient as its energy's derivative.

#include "solver/integrators/incremental_potential.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver/forces/spring_force.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr double time_step_s = 1.0 / 30.0;

std::vector<BlockProductKernel> kernels_this_processor_runs() {
  std::vector<BlockProductKernel> kernels{BlockProductKernel::portable};
  if (block_product_kernel() == BlockProductKernel::avx2)
    kernels.push_back(BlockProductKernel::avx2);
  return kernels;
}

TEST(SpringTerms, AreEachSpringsElasticAndViscousEnergyAndForceOnEveryKernel) {
  State state;
  SpringModel damped = test::random_model(40, 300, 10, 7, state);
  damped.springs(0, 1) = damped.springs(1, 0);  // a spring of zero length at x: no direction
  ASSERT_GT(damped.damping.maxCoeff(), 0.0);
  SpringModel undamped = damped;  // the kernels without the viscous terms
  undamped.damping.setZero();
  const Eigen::VectorXd x_n = state.x;
  Eigen::VectorXd x = state.x + 0.05 * test::random_free_vector(damped, 3);
  x.segment<3>(3 * damped.springs(0, 0)) = x.segment<3>(3 * damped.springs(0, 1));
  const StepPotential potential{time_step_s, &x_n, &x_n};

  for (const SpringModel* model : {&damped, &undamped}) {
    StepPotentialWorkspace workspace;
    prepare_step_potential(*model, potential, workspace);
    EXPECT_EQ(workspace.viscous, model == &damped);
    for (const BlockProductKernel kernel : kernels_this_processor_runs()) {
      const double total_j = evaluate_spring_terms(*model, time_step_s, x, workspace, kernel);
      double expected_total_j = 0.0;
      for (int s = 0; s < model->spring_count(); ++s) {
        const Eigen::Vector3d d =
            x.segment<3>(3 * model->springs(s, 0)) - x.segment<3>(3 * model->springs(s, 1));
        const Eigen::Vector3d u_n = workspace.start_directions.col(s);
        const double stretch_m = d.norm() - model->rest_length[s];
        const double rate_m = u_n.dot(d) - workspace.start_projections_m[s];
        const double viscous = model->damping[s] / time_step_s;
        const Eigen::Vector3d elastic_n =
            d.norm() < spring_length_epsilon
                ? Eigen::Vector3d::Zero()
                : Eigen::Vector3d(-model->stiffness[s] * stretch_m * d / d.norm());
        expected_total_j +=
            0.5 * model->stiffness[s] * stretch_m * stretch_m + 0.5 * viscous * rate_m * rate_m;
        const Eigen::Vector3d force_n = elastic_n - viscous * rate_m * u_n;
        EXPECT_LT((workspace.spring_forces.col(s) - force_n).norm(), 1e-12 * (1.0 + force_n.norm()))
            << s;
      }
      EXPECT_NEAR(total_j, expected_total_j, 1e-12 * (1.0 + expected_total_j));
    }
  }
}

TEST(StepPotential, GradientIsTheEnergysDerivativeWithCouplingsDampedOrNot) {
  for (const double damping : {0.05, 0.0}) {  // N s/m: with and without the viscous terms
    State state;
    SpringModel model = test::grid_model(6, 5, 0.1, 0.01, 200.0, damping, state);
    test::couple_triangle_edges(model, 11);
    model.pinned[0] = 1;
    finalize_model(model);
    const Eigen::VectorXd x_n = state.x;
    Eigen::VectorXd inertial = state.x;
    for (int p = 0; p < model.particle_count(); ++p) inertial[3 * p + 2] -= 0.01;
    const Eigen::VectorXd x = state.x + 0.01 * test::random_free_vector(model, 5);
    StepPotential potential{time_step_s, &x_n, &inertial};
    potential.air_damping = 0.3;
    StepPotentialWorkspace workspace;
    prepare_step_potential(model, potential, workspace);
    Eigen::VectorXd gradient;
    evaluate_step_potential(model, potential, x, workspace, &gradient);

    const Eigen::VectorXd direction = test::random_free_vector(model, 9);
    constexpr double step_m = 1e-6;
    const double slope =
        (evaluate_step_potential(model, potential, x + step_m * direction, workspace, nullptr) -
         evaluate_step_potential(model, potential, x - step_m * direction, workspace, nullptr)) /
        (2.0 * step_m);
    EXPECT_NEAR(gradient.dot(direction), slope, 1e-6 * std::abs(slope)) << damping;
    EXPECT_EQ(gradient.segment<3>(0), Eigen::Vector3d::Zero());  // pinned
  }
}

}  // namespace
}  // namespace tissu
