// Scenario files' solver options: the integrators' and their solvers' keys, the notes a scenario
// gets where an option cannot act as asked, and the strain limit.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tests/lib/scenario_errors.hpp"

namespace tissu {
namespace {

using test::minimal_scenario_error;
using ::testing::HasSubstr;

TEST(Scenario, ReadsProjectiveDynamicsOptions) {
  const Scenario s = parse_scenario(
      test::minimal_scenario, "dir/s.json",
      {"simulation.integrator=projective_dynamics",
       R"(simulation.pd={"global_solver": "colored_gauss_seidel", "iterations": 20, "tolerance": 1e-4})"});
  EXPECT_EQ(s.solver.integrator, Integrator::projective_dynamics);
  EXPECT_EQ(s.solver.pd.global_solver, PdGlobalSolver::colored_gauss_seidel);
  EXPECT_EQ(s.solver.pd.iterations, 20);
  EXPECT_DOUBLE_EQ(s.solver.pd.tolerance, 1e-4);
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "dir/s.json",
                           {"simulation.pd.global_solver=chebyshev"})
                .solver.pd.global_solver,
            PdGlobalSolver::chebyshev);
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "dir/s.json",
                           {"simulation.pd.global_solver=block_gauss_seidel"})
                .solver.pd.global_solver,
            PdGlobalSolver::block_gauss_seidel);
  EXPECT_THAT(test::scenario_error_of(test::minimal_scenario, {"simulation.pd.global_solver=sor"}),
              HasSubstr("simulation.pd.global_solver: expected one of \"direct\", \"jacobi\""));
}

TEST(Scenario, ReadsTheChebyshevOptions) {
  const ProjectiveDynamicsOptions defaults;
  const Scenario plain = parse_scenario(test::minimal_scenario, "dir/s.json");
  EXPECT_DOUBLE_EQ(plain.solver.pd.chebyshev_relaxation, defaults.chebyshev_relaxation);
  EXPECT_EQ(plain.solver.pd.chebyshev_delay, defaults.chebyshev_delay);
  const Scenario s = parse_scenario(
      test::minimal_scenario, "dir/s.json",
      {R"(simulation.pd={"global_solver": "chebyshev", "chebyshev_spectral_radius": 0.9,
                         "chebyshev_relaxation": 0.8, "chebyshev_delay": 5})"});
  EXPECT_DOUBLE_EQ(s.solver.pd.chebyshev_spectral_radius, 0.9);
  EXPECT_DOUBLE_EQ(s.solver.pd.chebyshev_relaxation, 0.8);
  EXPECT_EQ(s.solver.pd.chebyshev_delay, 5);
  EXPECT_DOUBLE_EQ(
      parse_scenario(test::minimal_scenario, "dir/s.json", {"simulation.pd.chebyshev_relaxation=1"})
          .solver.pd.chebyshev_relaxation,
      1.0);
}

TEST(Scenario, ChebyshevOptionsOutOfRangeAreNamed) {
  EXPECT_EQ(minimal_scenario_error("simulation.pd.chebyshev_relaxation", "0"),
            "dir/s.json: simulation.pd.chebyshev_relaxation: expected a number in (0, 1], got 0");
  EXPECT_THAT(minimal_scenario_error("simulation.pd.chebyshev_relaxation", "1.5"),
              HasSubstr("simulation.pd.chebyshev_relaxation: expected a number in (0, 1]"));
  EXPECT_THAT(minimal_scenario_error("simulation.pd.chebyshev_relaxation", "\"high\""),
              HasSubstr("simulation.pd.chebyshev_relaxation: expected a number in (0, 1]"));
  EXPECT_EQ(minimal_scenario_error("simulation.pd.chebyshev_delay", "-1"),
            "dir/s.json: simulation.pd.chebyshev_delay: expected an integer from 0 to 100000, "
            "got -1");
  EXPECT_THAT(minimal_scenario_error("simulation.pd.chebyshev_delay", "2.5"),
              HasSubstr("simulation.pd.chebyshev_delay: expected an integer from 0 to 100000"));
  EXPECT_THAT(minimal_scenario_error("simulation.pd.chebyshev_delay", "100001"),
              HasSubstr("simulation.pd.chebyshev_delay: expected an integer from 0 to 100000"));
}

TEST(Scenario, ReadsTheMinimisersOptionsAndPdsCheck) {
  const Scenario s = parse_scenario(
      test::minimal_scenario, "dir/s.json",
      {"simulation.integrator=newton",
       R"(simulation.newton={"tolerance": 0.01, "max_iterations": 7, "cg_max_iterations": 50,
           "preconditioner": "pd_matrix", "gradient_reduction": 0.3})",
       R"(simulation.quasi_newton={"tolerance": 0.02, "max_iterations": 9, "history": 3,
           "initial_hessian": "pd_matrix", "gradient_reduction": 0.2,
           "newton_fallback": false})",
       "simulation.pd.max_estimated_error=0", "simulation.obstacle_penalty=100",
       "simulation.friction_in_step=false"});
  const Scenario defaults = parse_scenario(test::minimal_scenario, "s.json", {});
  EXPECT_EQ(s.solver.integrator, Integrator::newton);
  EXPECT_DOUBLE_EQ(s.solver.obstacle_penalty, 100.0);
  EXPECT_FALSE(s.solver.friction_in_step);
  EXPECT_TRUE(defaults.solver.friction_in_step);
  EXPECT_DOUBLE_EQ(defaults.solver.obstacle_penalty, 0.0);
  EXPECT_EQ(minimal_scenario_error("simulation.obstacle_penalty", "-1"),
            "dir/s.json: simulation.obstacle_penalty: expected a number >= 0, got -1");
  EXPECT_DOUBLE_EQ(s.solver.newton.tolerance, 0.01);
  EXPECT_EQ(s.solver.newton.max_iterations, 7);
  EXPECT_EQ(s.solver.newton.cg_max_iterations, 50);
  EXPECT_EQ(s.solver.newton.preconditioner, NewtonPreconditioner::pd_matrix);
  EXPECT_DOUBLE_EQ(s.solver.newton.gradient_reduction, 0.3);
  EXPECT_DOUBLE_EQ(defaults.solver.newton.gradient_reduction, 0.1);
  EXPECT_THAT(minimal_scenario_error("simulation.newton.gradient_reduction", "-0.1"),
              HasSubstr("simulation.newton.gradient_reduction: expected"));
  EXPECT_EQ(defaults.solver.newton.preconditioner, NewtonPreconditioner::multigrid);
  EXPECT_THAT(minimal_scenario_error("simulation.newton.preconditioner", R"("jacobi")"),
              HasSubstr("simulation.newton.preconditioner: expected one of"));
  EXPECT_DOUBLE_EQ(s.solver.quasi_newton.tolerance, 0.02);
  EXPECT_EQ(s.solver.quasi_newton.max_iterations, 9);
  EXPECT_EQ(s.solver.quasi_newton.history, 3);
  EXPECT_EQ(s.solver.quasi_newton.initial_hessian, QuasiNewtonInitialHessian::pd_matrix);
  EXPECT_DOUBLE_EQ(s.solver.quasi_newton.gradient_reduction, 0.2);
  EXPECT_DOUBLE_EQ(defaults.solver.quasi_newton.gradient_reduction, 0.1);
  EXPECT_THAT(minimal_scenario_error("simulation.quasi_newton.gradient_reduction", "1.5"),
              HasSubstr("simulation.quasi_newton.gradient_reduction: expected"));
  EXPECT_FALSE(s.solver.quasi_newton.newton_fallback);
  EXPECT_TRUE(defaults.solver.quasi_newton.newton_fallback);
  EXPECT_THAT(minimal_scenario_error("simulation.quasi_newton.newton_fallback", "1"),
              HasSubstr("simulation.quasi_newton.newton_fallback: expected"));
  EXPECT_EQ(defaults.solver.quasi_newton.initial_hessian, QuasiNewtonInitialHessian::pd_multigrid);
  EXPECT_THAT(minimal_scenario_error("simulation.quasi_newton.initial_hessian", R"("multigrid")"),
              HasSubstr("simulation.quasi_newton.initial_hessian: expected one of"));
  EXPECT_DOUBLE_EQ(s.solver.pd.max_estimated_error, 0.0);
  EXPECT_EQ(minimal_scenario_error("simulation.newton.tolerance", "0"),
            "dir/s.json: simulation.newton.tolerance: expected a number in (0, 1], got 0");
  EXPECT_THAT(minimal_scenario_error("simulation.quasi_newton.history", "-1"),
              HasSubstr("simulation.quasi_newton.history: expected an integer from 0 to 1000"));
  EXPECT_THAT(minimal_scenario_error("simulation.newton.max_iteration", "3"),
              HasSubstr("simulation.newton.max_iteration: unknown key; did you mean "
                        "'max_iterations'?"));
  EXPECT_THAT(minimal_scenario_error("simulation.pd.max_estimated_error", "-1"),
              HasSubstr("simulation.pd.max_estimated_error: expected a number >= 0"));
}

TEST(Scenario, NotesImplicitEulerKeysThatTheDefaultIntegratorIgnores) {
  // no integrator named: the default (quasi-Newton) runs, and implicit Euler's keys set nothing
  const Scenario unnamed =
      parse_scenario(test::minimal_scenario, "dir/s.json", {"simulation.cg_tolerance=1e-8"});
  EXPECT_EQ(unnamed.solver.integrator, Integrator::quasi_newton);
  ASSERT_EQ(unnamed.notes.size(), 1u);
  EXPECT_EQ(unnamed.notes[0],
            "dir/s.json: simulation.cg_tolerance: read by \"implicit_euler\" only, and this "
            "scenario names no simulation.integrator: it runs the default, \"quasi_newton\" "
            "(before 2026-12-06 \"implicit_euler\"); name \"implicit_euler\" to use it");
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "dir/s.json",
                           {"simulation.cg_tolerance=1e-8", "simulation.cg_max_iterations=50"})
                .notes.size(),
            2u);
  // named, whichever it is: the scenario says what it wants
  for (const char* integrator : {"implicit_euler", "newton"}) {
    const Scenario named = parse_scenario(
        test::minimal_scenario, "dir/s.json",
        {"simulation.cg_tolerance=1e-8", std::string("simulation.integrator=") + integrator});
    EXPECT_TRUE(named.notes.empty()) << integrator;
  }
  EXPECT_TRUE(parse_scenario(test::minimal_scenario, "dir/s.json").notes.empty());
}

TEST(Scenario, NotesAMultigridInitialHessianAtALooseTolerance) {
  // the defaults (the V-cycle with gradient_reduction 0.1) need no note; the correction test alone
  // with the V-cycle does, unless the tolerance is tight
  EXPECT_TRUE(parse_scenario(test::minimal_scenario, "dir/s.json").notes.empty());
  const std::string alone = "simulation.quasi_newton.gradient_reduction=0";
  const Scenario loose = parse_scenario(test::minimal_scenario, "dir/s.json", {alone});
  ASSERT_EQ(loose.notes.size(), 1u);
  EXPECT_THAT(loose.notes[0], HasSubstr("dir/s.json: simulation.quasi_newton.initial_hessian: "
                                        "\"pd_multigrid\" stops steps early"));
  EXPECT_TRUE(parse_scenario(test::minimal_scenario, "dir/s.json",
                             {alone, "simulation.quasi_newton.tolerance=1e-3"})
                  .notes.empty());
  EXPECT_TRUE(parse_scenario(test::minimal_scenario, "dir/s.json",
                             {alone, R"(simulation.quasi_newton.initial_hessian="pd_matrix")"})
                  .notes.empty());
}

TEST(Scenario, NotesFrictionInTheStepWhereItCannotAct) {
  const Scenario alone =
      parse_scenario(test::minimal_scenario, "dir/s.json", {"simulation.friction_in_step=true"});
  ASSERT_EQ(alone.notes.size(), 1u);
  EXPECT_THAT(alone.notes[0], HasSubstr("dir/s.json: simulation.friction_in_step: acts only with "
                                        "simulation.obstacle_penalty > 0"));
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "dir/s.json",
                           {"simulation.friction_in_step=true", "simulation.obstacle_penalty=100",
                            "simulation.integrator=implicit_euler"})
                .notes.size(),
            1u);
  EXPECT_TRUE(
      parse_scenario(test::minimal_scenario, "dir/s.json",
                     {"simulation.friction_in_step=true", "simulation.obstacle_penalty=100"})
          .notes.empty());
  // on by default: no note where the scenario does not ask for it
  EXPECT_TRUE(parse_scenario(test::minimal_scenario, "dir/s.json", {}).notes.empty());
}

TEST(Scenario, ReadsTheStrainLimit) {
  EXPECT_DOUBLE_EQ(parse_scenario(test::minimal_scenario, "s.json").solver.strain_limit, 0.0);
  EXPECT_DOUBLE_EQ(parse_scenario(test::minimal_scenario, "s.json", {"simulation.strain_limit=0.1"})
                       .solver.strain_limit,
                   0.1);
  EXPECT_EQ(minimal_scenario_error("simulation.strain_limit", "-0.1"),
            "dir/s.json: simulation.strain_limit: expected a number between 0 and 10 (0: none; "
            "0.1: 10 %), got -0.1");
  // tearing by strain would be held back by the limit; tearing along cuts is not
  EXPECT_EQ(test::scenario_error_of(test::minimal_scenario,
                                    {"simulation.strain_limit=0.1", R"(tearing={"strain": 0.3})"}),
            "dir/s.json: simulation.strain_limit: expected 0 (none) when tearing by strain, which "
            "the limit would hold back, got 0.1");
  EXPECT_TRUE(
      parse_scenario(test::minimal_scenario, "s.json",
                     {"simulation.strain_limit=0.1",
                      R"(tearing={"cuts": [{"time": 0.5, "line": [[0, 0, 0], [1, 0, 0]]}]})"})
          .tearing.enabled);
}

}  // namespace
}  // namespace tissu
