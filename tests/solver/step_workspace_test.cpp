// A workspace kept across a change of model: every cache in it is keyed on the model's identity,
// so stepping a new model of the same sizes with a live workspace gives exactly what a fresh
// workspace gives.

#include "solver/step_workspace.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr double thickness_m = 0.004;

/// Two 8 x 8 sheets 3 mm apart (closer than the thickness, so self-collision pairs are cached),
/// the upper one shifted by a third of a cell.
SpringModel stacked_sheets(State& state) {
  State lower_state, upper_state;
  const SpringModel lower = test::grid_model(8, 8, 0.03, 1e-4, 200.0, 0.01, lower_state);
  const SpringModel upper = test::grid_model(8, 8, 0.03, 1e-4, 200.0, 0.01, upper_state);
  for (int p = 0; p < upper.particle_count(); ++p) {
    upper_state.x.segment<3>(3 * p) += Eigen::Vector3d(0.01, 0.01, 0.003);
  }
  return test::joined_models(lower, lower_state, upper, upper_state, state);
}

/// The same sizes as `model` (particles, springs, triangles), other content: springs and triangles
/// in reverse order, stiffer springs, heavier particles, one corner pinned.
SpringModel other_model_of_the_same_sizes(const SpringModel& model) {
  SpringModel other = model;
  other.springs = model.springs.colwise().reverse();
  other.rest_length = model.rest_length.reverse();
  other.stiffness = 1.5 * model.stiffness.reverse();
  other.damping = model.damping.reverse();
  other.kind.assign(model.kind.rbegin(), model.kind.rend());
  other.triangles = model.triangles.colwise().reverse();
  other.mass = 1.1 * model.mass;
  other.pinned[0] = 1;
  finalize_model(other);
  return other;
}

struct Case {
  const char* name;
  Integrator integrator;
  PdGlobalSolver global_solver = PdGlobalSolver::direct;
};

TEST(StepWorkspace, ANewModelOfTheSameSizesIsSteppedAsWithAFreshWorkspace) {
  State start;
  const SpringModel first = stacked_sheets(start);
  const SpringModel second = other_model_of_the_same_sizes(first);
  ASSERT_NE(first.identity, second.identity);
  for (const Case& c :
       std::vector<Case>{{"symplectic_euler", Integrator::symplectic_euler},
                         {"position_verlet", Integrator::position_verlet},
                         {"implicit_euler", Integrator::implicit_euler},
                         {"pd direct", Integrator::projective_dynamics},
                         {"pd jacobi", Integrator::projective_dynamics, PdGlobalSolver::jacobi},
                         {"newton", Integrator::newton},
                         {"quasi_newton", Integrator::quasi_newton}}) {
    SCOPED_TRACE(c.name);
    SolverParams params;
    params.integrator = c.integrator;
    params.pd.global_solver = c.global_solver;
    params.time_step = 2e-4;
    params.self_collision.enabled = true;
    params.self_collision.thickness_m = thickness_m;

    StepWorkspace live;
    State state = start;
    for (int n = 0; n < 3; ++n) ASSERT_NE(step(first, params, state, live), StepStatus::non_finite);
    ASSERT_FALSE(live.self_collision_pairs.pairs.empty());  // the first model's pairs are cached

    State with_live = start, with_fresh = start;
    StepWorkspace fresh;
    for (int n = 0; n < 3; ++n) {
      step(second, params, with_live, live);
      step(second, params, with_fresh, fresh);
    }
    EXPECT_TRUE((with_live.x.array() == with_fresh.x.array()).all());
    EXPECT_TRUE((with_live.v.array() == with_fresh.v.array()).all());
    EXPECT_EQ(live.self_collision_pairs.built_for_model, second.identity);
  }
}

TEST(StepWorkspace, EveryFinalizationIsANewIdentityAndACopyKeepsIt) {
  State state;
  SpringModel model = test::grid_model(3, 3, 0.1, 0.01, 10.0, 0.0, state);
  const std::uint64_t before = model.identity;
  EXPECT_NE(before, 0u);
  const SpringModel copy = model;
  EXPECT_EQ(copy.identity, before);
  finalize_model(model);
  EXPECT_GT(model.identity, before);
}

TEST(StepWorkspace, AModelNeverFinalizedIsRefused) {
  State state;
  SpringModel model = test::grid_model(3, 3, 0.1, 0.01, 10.0, 0.0, state);
  model.identity = 0;
  EXPECT_THROW(step(model, SolverParams{}, state), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
