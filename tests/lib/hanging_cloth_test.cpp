// A cloth hanging from its top edge, stepped by the solver: the whole foundation working together.

#include <gtest/gtest.h>

#include "solver/energy.hpp"
#include "solver/forces/accumulate_forces.hpp"
#include "solver/step.hpp"
#include "topology/apply_pins.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/compile.hpp"
#include "topology/grid_mesh.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;

CompiledCloth hanging_cloth(int cells, ClothComplex& lcc) {
  GridOptions grid;
  grid.width = 1.0;
  grid.height = 1.0;
  grid.cells_u = cells;
  grid.cells_v = cells;
  SpringSettings springs;
  springs.structural = {true, 500.0, 0.5};
  springs.bending = {true, 2.0, 0.01};
  build_cloth_complex(make_grid_mesh(grid), density_kg_per_m2, springs, lcc);
  PinSelector top;
  top.side = Side::top;
  apply_pins(lcc, {top}, ClothFrame{});
  return compile(lcc);
}

SolverParams still_air(Integrator integrator, double time_step_s) {
  SolverParams params;
  params.integrator = integrator;
  params.time_step = time_step_s;
  params.environment.wind.air_density = 0.0;  // no aerodynamic forces
  return params;
}

double total_energy(const CompiledCloth& c, const SolverParams& p) {
  return kinetic_energy(c.model, c.state) +
         potential_energy(c.model, p.environment.gravity, c.state);
}

double max_speed(const State& state) {
  return state.v.reshaped(3, state.v.size() / 3).colwise().norm().maxCoeff();
}

TEST(HangingCloth, DampedImplicitEulerNeverIncreasesTotalEnergy) {
  ClothComplex lcc;
  CompiledCloth cloth = hanging_cloth(12, lcc);
  // start from a swing so that springs stretch, compress and bend
  for (int i = 0; i < cloth.model.particle_count(); ++i) {
    if (!cloth.model.pinned[i]) cloth.state.v[3 * i + 1] = 0.5;
  }
  const SolverParams params = still_air(Integrator::implicit_euler, 1.0 / 200.0);
  StepWorkspace workspace;
  double previous_J = total_energy(cloth, params);
  const double initial_J = previous_J;
  for (int n = 0; n < 1000; ++n) {
    ASSERT_EQ(step(cloth.model, params, cloth.state, workspace), StepStatus::ok) << "step " << n;
    const double energy_J = total_energy(cloth, params);
    ASSERT_LE(energy_J, previous_J + 1e-12 * std::abs(initial_J)) << "step " << n;
    previous_J = energy_J;
  }
  EXPECT_LT(previous_J, initial_J);
}

class HangingClothAtRest : public ::testing::TestWithParam<Integrator> {};

TEST_P(HangingClothAtRest, ReachesRestWithThePinsCarryingTheWholeWeight) {
  ClothComplex lcc;
  CompiledCloth cloth = hanging_cloth(10, lcc);
  const bool implicit = GetParam() == Integrator::implicit_euler;
  SolverParams params = still_air(GetParam(), implicit ? 1.0 / 100.0 : 1.0 / 2000.0);
  params.environment.air_damping = 2.0;  // 1/s: settles the pendulum modes springs cannot damp
  StepWorkspace workspace;
  const int steps = static_cast<int>(15.0 / params.time_step);
  for (int n = 0; n < steps; ++n) {
    ASSERT_EQ(step(cloth.model, params, cloth.state, workspace), StepStatus::ok) << "step " << n;
  }
  EXPECT_LT(max_speed(cloth.state), 1e-4);  // m/s

  // sum of all forces = M g, internal forces cancelling; at rest the free particles feel none,
  // so what the pins hold, the force on them, is the whole weight
  Eigen::VectorXd force;
  ForceWorkspace force_workspace;
  accumulate_forces(cloth.model, params.environment, cloth.state.time, cloth.state.x,
                    Eigen::VectorXd::Zero(cloth.state.v.size()), force_workspace, force);
  Eigen::Vector3d held_N = Eigen::Vector3d::Zero();
  for (int i = 0; i < cloth.model.particle_count(); ++i) {
    if (cloth.model.pinned[i]) held_N += force.segment<3>(3 * i);
  }
  const Eigen::Vector3d weight_N = total_mass(cloth.model) * params.environment.gravity;
  EXPECT_LT((held_N - weight_N).norm(), 0.005 * weight_N.norm())
      << "held " << held_N.transpose() << " N, weight " << weight_N.transpose() << " N";
  EXPECT_NEAR(total_mass(cloth.model), density_kg_per_m2 * 1.0, 1e-15);
}

INSTANTIATE_TEST_SUITE_P(Integrators, HangingClothAtRest,
                         ::testing::Values(Integrator::implicit_euler, Integrator::position_verlet),
                         [](const auto& info) {
                           return info.param == Integrator::implicit_euler ? "implicit_euler"
                                                                           : "position_verlet";
                         });

}  // namespace
}  // namespace tissu
