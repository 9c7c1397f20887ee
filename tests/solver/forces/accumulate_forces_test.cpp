#include "solver/forces/accumulate_forces.hpp"

#include <gtest/gtest.h>

#include <random>

#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

Environment windy_environment() {
  Environment environment;
  environment.air_damping = 0.3;
  environment.wind.velocity = Eigen::Vector3d(1.0, 2.0, 8.0);
  environment.wind.gust_amplitude = 0.5;
  environment.wind.gust_frequency = 0.8;
  return environment;
}

// a 20 x 20 grid, perturbed and moving, so that every spring and triangle does something
SpringModel perturbed_grid(State& state) {
  SpringModel model = test::grid_model(20, 20, 0.05, 0.002, 500.0, 0.01, state);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Eigen::Index i = 0; i < state.x.size(); ++i) {
    state.x[i] += 0.01 * unit(rng);
    state.v[i] = unit(rng);
  }
  return model;
}

Eigen::VectorXd forces_with_threads(int threads, const SpringModel& model,
                                    const Environment& environment, const State& state) {
  const test::ScopedThreadCount count(threads);
  ForceWorkspace workspace;
  Eigen::VectorXd force;
  accumulate_forces(model, environment, 0.37, state.x, state.v, workspace, force);
  return force;
}

TEST(AccumulateForces, BitwiseIdenticalForOneAndTwoThreads) {
  State state;
  const SpringModel model = perturbed_grid(state);
  ASSERT_GE(model.particle_count(), 300);
  const Environment environment = windy_environment();
  const Eigen::VectorXd one = forces_with_threads(1, model, environment, state);
  const Eigen::VectorXd two = forces_with_threads(2, model, environment, state);
  const Eigen::VectorXd three = forces_with_threads(3, model, environment, state);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_GT(one.norm(), 0.0);
  for (Eigen::Index i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i], two[i]) << "dof " << i;  // exact comparison on purpose
    ASSERT_EQ(one[i], three[i]) << "dof " << i;
  }
}

TEST(AccumulateForces, InternalForcesSumToZero) {
  State state;
  const SpringModel model = perturbed_grid(state);
  Environment environment;
  environment.gravity.setZero();
  environment.wind.air_density = 0.0;
  ForceWorkspace workspace;
  Eigen::VectorXd force;
  accumulate_forces(model, environment, 0.0, state.x, state.v, workspace, force);
  const Eigen::Vector3d total = force.reshaped(3, model.particle_count()).rowwise().sum();
  EXPECT_LT(total.norm(), 1e-9 * force.norm());
}

TEST(AccumulateForces, GravityAndAirDampingOnAFreeParticle) {
  SpringModel model;
  model.mass = Eigen::VectorXd::Constant(1, 2.0);
  model.pinned = {0};
  model.springs.resize(0, 2);
  model.triangles.resize(0, 3);
  finalize_model(model);
  const Eigen::VectorXd x = Eigen::Vector3d(1.0, 2.0, 3.0);
  const Eigen::VectorXd v = Eigen::Vector3d(0.5, 0.0, -1.0);
  Environment environment;
  environment.air_damping = 0.1;
  ForceWorkspace workspace;
  Eigen::VectorXd force;
  accumulate_forces(model, environment, 0.0, x, v, workspace, force);
  const Eigen::Vector3d expected = 2.0 * environment.gravity - 0.1 * 2.0 * Eigen::Vector3d(v);
  EXPECT_LT((Eigen::Vector3d(force) - expected).norm(), 1e-14);
}

TEST(AccumulateForces, RestStateHasNoSpringForce) {
  State state;
  const SpringModel model = test::grid_model(5, 4, 0.1, 0.01, 100.0, 0.5, state);
  Environment environment;
  environment.gravity.setZero();
  ForceWorkspace workspace;
  Eigen::VectorXd force;
  accumulate_forces(model, environment, 0.0, state.x, state.v, workspace, force);
  EXPECT_LT(force.cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace tissu
