#include "solver/forces/force_jacobian.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "solver/forces/accumulate_forces.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr double fd_step = 1e-6;  // m or m/s

// gravity and air damping on, wind off (air density 0): the forces the Jacobians cover exactly
Environment environment_without_wind() {
  Environment environment;
  environment.gravity = Eigen::Vector3d(0.0, -9.81, 1.0);
  environment.air_damping = 0.7;
  environment.wind.velocity = Eigen::Vector3d(3.0, 0.0, 0.0);
  environment.wind.air_density = 0.0;
  return environment;
}

// central differences of accumulate_forces with respect to x (wrt_velocity false) or v
Eigen::MatrixXd finite_difference_jacobian(const SpringModel& model, const Environment& environment,
                                           const State& state, bool wrt_velocity) {
  const Eigen::Index dofs = state.x.size();
  Eigen::MatrixXd jacobian(dofs, dofs);
  ForceWorkspace workspace;
  Eigen::VectorXd plus, minus;
  for (Eigen::Index dof = 0; dof < dofs; ++dof) {
    State perturbed = state;
    Eigen::VectorXd& variable = wrt_velocity ? perturbed.v : perturbed.x;
    variable[dof] += fd_step;
    accumulate_forces(model, environment, 0.0, perturbed.x, perturbed.v, workspace, plus);
    variable[dof] -= 2.0 * fd_step;
    accumulate_forces(model, environment, 0.0, perturbed.x, perturbed.v, workspace, minus);
    jacobian.col(dof) = (plus - minus) / (2.0 * fd_step);
  }
  return jacobian;
}

TEST(ForceJacobian, PositionJacobianMatchesFiniteDifferences) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    State state;
    const SpringModel model = test::random_model(6, 14, 4, seed, state);
    // the viscous force depends on x through u only when moving: its x-derivative is left out
    state.v.setZero();
    const Environment environment = environment_without_wind();
    ForceJacobianWorkspace workspace;
    Eigen::SparseMatrix<double> dfdx;
    force_position_jacobian(model, state.x, {}, workspace, dfdx);
    const Eigen::MatrixXd analytic = Eigen::MatrixXd(dfdx);
    const Eigen::MatrixXd fd = finite_difference_jacobian(model, environment, state, false);
    EXPECT_LT((analytic - fd).cwiseAbs().maxCoeff(), 1e-5 * analytic.cwiseAbs().maxCoeff())
        << "seed " << seed;
    EXPECT_LT((analytic - analytic.transpose()).cwiseAbs().maxCoeff(), 1e-12 * analytic.norm());
  }
}

TEST(ForceJacobian, VelocityJacobianMatchesFiniteDifferences) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    State state;
    const SpringModel model = test::random_model(6, 14, 4, seed, state);
    const Environment environment = environment_without_wind();
    ForceJacobianWorkspace workspace;
    Eigen::SparseMatrix<double> dfdv;
    force_velocity_jacobian(model, environment, state.x, workspace, dfdv);
    const Eigen::MatrixXd analytic = Eigen::MatrixXd(dfdv);
    const Eigen::MatrixXd fd = finite_difference_jacobian(model, environment, state, true);
    EXPECT_LT((analytic - fd).cwiseAbs().maxCoeff(), 1e-6 * analytic.cwiseAbs().maxCoeff())
        << "seed " << seed;
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(analytic).eigenvalues();
    EXPECT_LE(eigenvalues.maxCoeff(), 1e-12);
  }
}

TEST(ForceJacobian, ClampedPositionJacobianIsNegativeSemidefinite) {
  State state;
  const SpringModel model = test::random_model(10, 30, 0, 11, state);
  ForceJacobianWorkspace workspace;
  Eigen::SparseMatrix<double> exact, clamped;
  force_position_jacobian(model, state.x, {}, workspace, exact);
  force_position_jacobian(model, state.x, {.clamp_compressed_springs = true}, workspace, clamped);
  const Eigen::VectorXd exact_eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(exact)).eigenvalues();
  const Eigen::VectorXd clamped_eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(clamped)).eigenvalues();
  EXPECT_GT(exact_eigenvalues.maxCoeff(), 1e-6);  // the model has compressed springs
  EXPECT_LE(clamped_eigenvalues.maxCoeff(), 1e-9 * model.stiffness.maxCoeff());
}

TEST(ForceJacobian, WorkspaceFollowsAModelChange) {
  State state_a, state_b;
  const SpringModel model_a = test::random_model(12, 30, 0, 3, state_a);
  const SpringModel model_b = test::random_model(12, 25, 0, 4, state_b);
  ForceJacobianWorkspace reused;
  Eigen::SparseMatrix<double> dfdx;
  force_position_jacobian(model_a, state_a.x, {}, reused, dfdx);
  force_position_jacobian(model_b, state_b.x, {}, reused, dfdx);
  ForceJacobianWorkspace fresh;
  Eigen::SparseMatrix<double> expected;
  force_position_jacobian(model_b, state_b.x, {}, fresh, expected);
  EXPECT_EQ(Eigen::MatrixXd(dfdx), Eigen::MatrixXd(expected));
}

}  // namespace
}  // namespace tissu
