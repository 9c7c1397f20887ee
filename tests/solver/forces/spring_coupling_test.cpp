// Couplings between the stretches of two springs (Delingette's angular terms): forces are minus
// the energy's gradient, the Jacobian is the forces' derivative, and implicit Euler steps a
// coupled cloth deterministically to rest.

#include "solver/forces/spring_coupling.hpp"

#include <gtest/gtest.h>

#include <random>

#include "solver/energy.hpp"
#include "solver/forces/accumulate_forces.hpp"
#include "solver/forces/force_jacobian.hpp"
#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr double fd_step = 1e-6;  // m

/// A 3 x 3 grid of coupled triangles, its particles moved off the rest shape in 3D.
SpringModel deformed_coupled_grid(unsigned seed, State& state) {
  SpringModel model = test::grid_model(3, 3, 0.1, 0.01, 500.0, 0.0, state);
  test::couple_triangle_edges(model, seed);
  std::mt19937 rng(seed + 100);
  std::uniform_real_distribution<double> offset(-0.02, 0.02);
  for (Eigen::Index i = 0; i < state.x.size(); ++i) state.x[i] += offset(rng);
  return model;
}

TEST(SpringCoupling, ForcesAreMinusTheEnergyGradient) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    State state;
    const SpringModel model = deformed_coupled_grid(seed, state);
    Environment still;
    still.gravity.setZero();
    ForceWorkspace workspace;
    Eigen::VectorXd force;
    accumulate_forces(model, still, 0.0, state.x, state.v, workspace, force);
    for (Eigen::Index dof = 0; dof < state.x.size(); ++dof) {
      State plus = state, minus = state;
      plus.x[dof] += fd_step;
      minus.x[dof] -= fd_step;
      const double gradient = (potential_energy(model, still.gravity, plus) -
                               potential_energy(model, still.gravity, minus)) /
                              (2 * fd_step);
      EXPECT_NEAR(force[dof], -gradient, 1e-6 * force.cwiseAbs().maxCoeff())
          << "seed " << seed << ", dof " << dof;
    }
  }
}

TEST(SpringCoupling, PositionJacobianMatchesFiniteDifferences) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    State state;
    const SpringModel model = deformed_coupled_grid(seed, state);
    Environment still;
    ForceJacobianWorkspace jacobian_workspace;
    Eigen::SparseMatrix<double> dfdx;
    force_position_jacobian(model, state.x, {}, jacobian_workspace, dfdx);
    const Eigen::MatrixXd analytic(dfdx);
    ForceWorkspace workspace;
    Eigen::VectorXd plus, minus;
    double worst = 0.0;
    for (Eigen::Index dof = 0; dof < state.x.size(); ++dof) {
      Eigen::VectorXd x = state.x;
      x[dof] += fd_step;
      accumulate_forces(model, still, 0.0, x, state.v, workspace, plus);
      x[dof] -= 2 * fd_step;
      accumulate_forces(model, still, 0.0, x, state.v, workspace, minus);
      worst = std::max(worst,
                       (analytic.col(dof) - (plus - minus) / (2 * fd_step)).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-5 * analytic.cwiseAbs().maxCoeff()) << "seed " << seed;
    EXPECT_LT((analytic - analytic.transpose()).cwiseAbs().maxCoeff(), 1e-12 * analytic.norm());
  }
}

TEST(SpringCoupling, FinalizeRefusesCouplingSpringsWhoseEndsShareNoSpring) {
  State state;
  SpringModel model = test::grid_model(3, 3, 0.1, 0.01, 500.0, 0.0, state);
  model.couplings.resize(1, 2);
  model.couplings << 0, model.spring_count() - 1;  // a spring at one corner, one at the other
  model.coupling_stiffness.setConstant(1, 10.0);
  EXPECT_THROW(finalize_model(model), std::invalid_argument);
}

TEST(SpringCoupling, ImplicitEulerStepsACoupledClothToRestOnAnyThreadCount) {
  State state;
  SpringModel model = test::grid_model(8, 8, 0.05, 0.001, 200.0, 0.05, state);
  // couplings a third of the springs' stiffness, positive and negative, as Delingette's are
  test::couple_triangle_edges(model, 5);
  model.coupling_stiffness = model.coupling_stiffness.cwiseMax(-60.0).cwiseMin(60.0);
  for (int column = 0; column < 8; ++column) model.pinned[7 * 8 + column] = 1;
  finalize_model(model);
  SolverParams params;
  params.integrator = Integrator::implicit_euler;
  params.time_step = 1.0 / 200.0;
  params.environment.air_damping = 5.0;
  const auto [one, two] = test::step_with_one_and_two_threads(model, params, state, 1000);
  EXPECT_EQ(one.x, two.x);
  EXPECT_TRUE(one.x.allFinite());
  EXPECT_LT(one.v.cwiseAbs().maxCoeff(), 1e-3);  // at rest, hanging
}

}  // namespace
}  // namespace tissu
