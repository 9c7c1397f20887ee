// stats.csv's solver_iterations: the integrator's iterations over each frame's steps, the work
// that sets a step's price (what a researcher comparing integrators or meshes reads first).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

/// A 0.5 m sheet of 6 x 6 cells hanging from its top side, 6 frames of `substeps` steps with
/// `integrator` and its `extra` settings; the stepped frames' solver_iterations (frame 0, the
/// start, has no steps).
std::vector<int> iterations_per_frame(const std::string& integrator, int substeps,
                                      const std::string& extra = "") {
  const std::string json = R"({
  "cloth": { "grid": { "size": [0.5, 0.5], "resolution": [6, 6] }, "density": 0.2,
             "springs": { "structural": { "stiffness": 500, "damping": 0.2 },
                          "bending": { "stiffness": 0.01 } } },
  "pins": [ { "side": "top" } ],
  "simulation": { "integrator": ")" +
                           integrator + R"(", "frames": 6, "substeps": )" +
                           std::to_string(substeps) + extra +
                           R"( },
  "output": { "meshes": false, "viewer": false, "point_cache": false },
  "render": { "enabled": false }
})";
  RunOptions options;
  options.output_dir = test::fresh_temp_dir("solver_iterations/" + integrator);
  std::vector<int> iterations;
  options.on_frame = [&](const FrameStats& row) {
    if (row.frame > 0) iterations.push_back(row.solver_iterations);
  };
  const RunResult result = run_scenario(parse_scenario(json, "sheet.json"), options);
  EXPECT_TRUE(result.ok) << result.failure;
  return iterations;
}

int total(const std::vector<int>& counts) {
  int sum = 0;
  for (int count : counts) sum += count;
  return sum;
}

TEST(SolverIterations, EveryStepOfAMinimiserOrAnImplicitSolveCountsAtLeastOne) {
  for (const std::string integrator : {"implicit_euler", "newton", "quasi_newton"}) {
    const std::vector<int> iterations = iterations_per_frame(integrator, 3);
    ASSERT_EQ(iterations.size(), 6u) << integrator;
    // the sheet falls from rest: no step starts at its minimiser
    for (int count : iterations) EXPECT_GE(count, 3) << integrator;
  }
}

TEST(SolverIterations, ProjectiveDynamicsCountsItsLocalGlobalIterations) {
  // no tolerance: exactly `iterations` per step
  const std::vector<int> iterations =
      iterations_per_frame("projective_dynamics", 2, R"(, "pd": { "iterations": 7 })");
  ASSERT_EQ(iterations.size(), 6u);
  for (int count : iterations) EXPECT_EQ(count, 14);
}

TEST(SolverIterations, ATighterToleranceTakesMoreIterations) {
  const int loose =
      total(iterations_per_frame("quasi_newton", 1, R"(, "quasi_newton": { "tolerance": 1e-1 })"));
  const int tight =
      total(iterations_per_frame("quasi_newton", 1, R"(, "quasi_newton": { "tolerance": 1e-4 })"));
  EXPECT_GT(tight, loose);
}

TEST(SolverIterations, ExplicitIntegratorsHaveNone) {
  const std::vector<int> iterations = iterations_per_frame("symplectic_euler", 50);
  ASSERT_EQ(iterations.size(), 6u);
  for (int count : iterations) EXPECT_EQ(count, 0);
}

}  // namespace
}  // namespace tissu
