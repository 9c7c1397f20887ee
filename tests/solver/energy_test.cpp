#include "solver/energy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

TEST(Energy, TwoParticlesOnOneSpring) {
  SpringModel model;
  model.mass = Eigen::Vector2d(2.0, 3.0);
  model.pinned = {0, 0};
  model.springs.resize(1, 2);
  model.springs << 0, 1;
  model.rest_length = Eigen::VectorXd::Constant(1, 1.0);
  model.stiffness = Eigen::VectorXd::Constant(1, 10.0);
  model.damping = Eigen::VectorXd::Zero(1);
  model.kind = {SpringKind::structural};
  model.triangles.resize(0, 3);
  finalize_model(model);
  State state;
  state.x.resize(6);
  state.x << 0.0, 0.0, 1.0, 1.5, 0.0, 2.0;
  state.v.resize(6);
  state.v << 1.0, 0.0, 0.0, 0.0, 2.0, 0.0;
  const Eigen::Vector3d gravity(0.0, 0.0, -10.0);
  EXPECT_DOUBLE_EQ(total_mass(model), 5.0);
  EXPECT_DOUBLE_EQ(kinetic_energy(model, state), 0.5 * 2.0 * 1.0 + 0.5 * 3.0 * 4.0);
  // spring: |d| = sqrt(1.5^2 + 1) ; gravity: m g z
  const double stretch = std::sqrt(1.5 * 1.5 + 1.0) - 1.0;
  EXPECT_DOUBLE_EQ(potential_energy(model, gravity, state),
                   0.5 * 10.0 * stretch * stretch + 2.0 * 10.0 * 1.0 + 3.0 * 10.0 * 2.0);
}

// total energy over 1 s (5000 steps) of an undamped, windless, weightless, perturbed sheet (J)
std::vector<double> energy_history(Integrator integrator) {
  State state;
  const SpringModel model = test::grid_model(8, 8, 0.05, 0.01, 100.0, 0.0, state);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Eigen::Index i = 0; i < state.x.size(); ++i) state.x[i] += 0.005 * unit(rng);
  SolverParams params;
  params.integrator = integrator;
  params.time_step = 2e-4;
  params.environment.gravity.setZero();
  params.environment.wind.air_density = 0.0;
  StepWorkspace workspace;
  std::vector<double> energies;
  for (int n = 0; n < 5000; ++n) {
    EXPECT_EQ(step(model, params, state, workspace), StepStatus::ok);
    energies.push_back(kinetic_energy(model, state) +
                       potential_energy(model, params.environment.gravity, state));
  }
  return energies;
}

TEST(Energy, SymplecticIntegratorsKeepItBounded) {
  for (const Integrator integrator : {Integrator::symplectic_euler, Integrator::position_verlet}) {
    const std::vector<double> energies = energy_history(integrator);
    const auto [lowest, highest] = std::minmax_element(energies.begin(), energies.end());
    // the energy oscillates (it is not exactly conserved, symplectic Euler less well) ...
    EXPECT_LT(*highest - *lowest, 0.1 * energies.front()) << static_cast<int>(integrator);
    // ... but does not drift: same mean over the first and the last fifth
    const auto mean = [](auto first, auto last) {
      return std::accumulate(first, last, 0.0) / static_cast<double>(last - first);
    };
    const auto fifth = static_cast<std::ptrdiff_t>(energies.size() / 5);
    EXPECT_NEAR(mean(energies.end() - fifth, energies.end()),
                mean(energies.begin(), energies.begin() + fifth), 0.01 * energies.front())
        << static_cast<int>(integrator);
  }
}

TEST(Energy, ImplicitEulerDissipatesIt) {
  const std::vector<double> energies = energy_history(Integrator::implicit_euler);
  EXPECT_LT(energies.back(), energies.front());
  for (std::size_t n = 1; n < energies.size(); ++n) {
    EXPECT_LE(energies[n], energies[n - 1] + 1e-9) << "step " << n;
  }
}

}  // namespace
}  // namespace tissu
