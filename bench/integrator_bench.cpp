// The integrators on stiff cloth at frame-rate steps (issue 16). Two families:
//
// HangingSheet/<method>/<N>: Liu et al. 2013's sheet, 1 m x 1 m, N x N particles, structural,
// shear and bending springs of 3000 N/m, 1 kg in all, the two corners of one edge pinned, no
// drag, released horizontal from rest; h = 1/30 s, one step per frame, `sheet_frames` frames.
// Counters: ms_per_frame (one run of all the frames; --benchmark_repetitions for medians),
// iterations per step (Newton or L-BFGS iterations, PD local/global iterations, CG iterations of
// implicit_euler), preconditioner solves per step (solves with the PD matrix or multigrid V-cycles:
// what sets a step's price), unconverged steps, lowest point after the last frame (m, the pins at
// 0) and the structural springs' stretch (%): median, 90th percentile and largest (at the two
// pinned corners, which carry the whole weight: it grows with the resolution); and the gap to the
// converged trajectory (Newton to a tight tolerance, run once per size), mean and largest
// particle distance over the 90 frames in % of the sheet's side: gap_* at the same h (how far
// the method is from the backward-Euler trajectory it claims to follow) and gap_h16_* at h/16
// (how far from the motion itself; N = 41). A method with a small tolerance but a large gap
// stops its iterations before it has converged.
//
// Demo/<scenario>/<config>: a shipped scenario with implicit_euler and 10 steps per frame (the
// demos' integrator before issue 16) and with the others, at 10 or 1 steps per frame (xN): wall
// time per simulated second and the shape gap to today's run at the same material points, every
// second (mean and max, % of the cloth's rest diagonal); and converged_gap_*, the same to the
// converged backward-Euler motion at one step per frame (Newton to 1e-4; for scenes that tear,
// whose tears are checked once per step, implicit Euler at 100 steps per frame; none with
// TISSU_SHEET_REFERENCES=0). Also the edges torn in all and the pieces at the end.
//
// Results and the machine: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench/recorded_run.hpp"
#include "solver/step.hpp"
#include "topology/apply_pins.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/compile.hpp"
#include "topology/grid_mesh.hpp"

namespace tissu {
namespace {

constexpr int sheet_frames = 90;
constexpr double sheet_stiffness_n_per_m = 3000.0;

struct Method {
  Integrator integrator;
  PdGlobalSolver global_solver = PdGlobalSolver::direct;
  double tolerance = 0.0;  ///< Newton's or quasi-Newton's tolerance; 0: the default
  NewtonPreconditioner preconditioner = NewtonPreconditioner::multigrid;
  QuasiNewtonInitialHessian initial_hessian = QuasiNewtonInitialHessian::pd_matrix;
  double gradient_reduction = 0.0;  ///< quasi-Newton's
};

CompiledCloth hanging_sheet(int particles_per_side) {
  GridOptions grid;
  grid.cells_u = grid.cells_v = particles_per_side - 1;
  grid.u_axis = Eigen::Vector3d::UnitX();
  grid.v_axis = Eigen::Vector3d::UnitY();
  SpringSettings springs;
  springs.structural = {true, sheet_stiffness_n_per_m, 0.0};
  springs.shear = {true, sheet_stiffness_n_per_m, 0.0};
  springs.bending = {true, sheet_stiffness_n_per_m, 0.0};
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(grid), 1.0, springs, lcc);  // 1 kg/m^2 over 1 m^2
  PinSelector corners;
  corners.kind = PinSelector::Kind::corners;
  corners.corners = {Corner::top_left, Corner::top_right};
  apply_pins(lcc, {corners}, ClothFrame{grid.u_axis, grid.v_axis});
  return compile(lcc);
}

/// Preconditioner solves in the last step (a solve with the PD matrix, or a multigrid V-cycle):
/// Newton's conjugate-gradient iterations, quasi-Newton's (and its Newton fallback's conjugate-
/// gradient iterations) and PD's iterations.
int preconditioner_solves_of(const SolverParams& params, const StepWorkspace& workspace) {
  if (params.integrator == Integrator::newton) return workspace.newton.cg_iterations;
  if (params.integrator == Integrator::quasi_newton) {
    const QuasiNewtonWorkspace& qn = workspace.quasi_newton;
    return qn.iterations + (qn.newton_iterations > 0 ? workspace.newton.cg_iterations : 0);
  }
  return last_step_iterations(params, workspace);
}

SolverParams sheet_params(const Method& method, int steps_per_frame) {
  SolverParams params;
  params.time_step = 1.0 / (30.0 * steps_per_frame);
  params.integrator = method.integrator;
  params.pd.global_solver = method.global_solver;
  params.newton.preconditioner = method.preconditioner;
  params.quasi_newton.initial_hessian = method.initial_hessian;
  params.quasi_newton.gradient_reduction = method.gradient_reduction;
  if (method.tolerance > 0.0) {
    params.newton.tolerance = params.quasi_newton.tolerance = method.tolerance;
  }
  return params;
}

/// One run of the sheet: every frame's positions (3#P, m) when `record`, and what it took.
struct SheetRun {
  std::vector<Eigen::VectorXd> frames;
  State last;
  double wall_s = 0.0;
  long iterations = 0;
  long preconditioner_solves = 0;
  int unconverged = 0;
  bool finite = true;
};

SheetRun run_sheet(const CompiledCloth& cloth, const SolverParams& params, int steps_per_frame,
                   bool record) {
  SheetRun run;
  run.last = cloth.state;
  StepWorkspace workspace;
  const auto start = std::chrono::steady_clock::now();
  for (int frame = 0; frame < sheet_frames && run.finite; ++frame) {
    for (int k = 0; k < steps_per_frame && run.finite; ++k) {
      const StepStatus status = step(cloth.model, params, run.last, workspace);
      run.finite = status != StepStatus::non_finite;
      run.unconverged += status == StepStatus::not_converged;
      run.iterations += last_step_iterations(params, workspace);
      run.preconditioner_solves += preconditioner_solves_of(params, workspace);
    }
    if (record) run.frames.push_back(run.last.x);
  }
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

/// Whether to run the converged references: not with TISSU_SHEET_REFERENCES=0 in the environment.
bool references_wanted() {
  const char* wanted = std::getenv("TISSU_SHEET_REFERENCES");
  return !(wanted && std::string(wanted) == "0");
}

/// The converged trajectory the others are measured against: Newton to 1e-4 (at 41 x 41 within
/// 0.05 % of the sheet's side of Newton to 1e-6) with `steps_per_frame` steps of
/// h = 1/(30 steps_per_frame) s; run once per size and kept. Sizes above 128 x 128 (above 41 x 41
/// at h/16) have none (a reference there takes an hour or more), and
/// none is run with TISSU_SHEET_REFERENCES=0 in the environment (timings only: a reference takes
/// minutes, and the gaps are the same on any thread count).
const std::vector<Eigen::VectorXd>* reference_trajectory(int n, int steps_per_frame) {
  if (n > 128 || (steps_per_frame > 1 && n > 41) || !references_wanted()) return nullptr;
  static std::map<std::pair<int, int>, std::vector<Eigen::VectorXd>> references;
  auto found = references.find({n, steps_per_frame});
  if (found == references.end()) {
    SolverParams params =
        sheet_params({Integrator::newton, PdGlobalSolver::direct, 1e-4}, steps_per_frame);
    params.newton.max_iterations = 100;
    params.newton.cg_max_iterations = 1000;
    found = references
                .emplace(std::make_pair(n, steps_per_frame),
                         run_sheet(hanging_sheet(n), params, steps_per_frame, true).frames)
                .first;
  }
  return &found->second;
}

/// Mean over the frames of the particles' mean distance to the reference, and the largest
/// distance seen, in % of the sheet's side (1 m).
std::pair<double, double> trajectory_gap_pct(const std::vector<Eigen::VectorXd>& frames,
                                             const std::vector<Eigen::VectorXd>& reference) {
  double mean_m = 0.0, max_m = 0.0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Eigen::Index particles = frames[f].size() / 3;
    double frame_m = 0.0;
    for (Eigen::Index p = 0; p < particles; ++p) {
      const double d_m = (frames[f].segment<3>(3 * p) - reference[f].segment<3>(3 * p)).norm();
      frame_m += d_m / particles;
      max_m = std::max(max_m, d_m);
    }
    mean_m += frame_m / frames.size();
  }
  return {100.0 * mean_m, 100.0 * max_m};
}

void BM_HangingSheet(benchmark::State& bench, Method method) {
  const int n = static_cast<int>(bench.range(0));
  const SolverParams params = sheet_params(method, 1);
  const CompiledCloth cloth = hanging_sheet(n);
  const SpringModel& model = cloth.model;
  const std::vector<Eigen::VectorXd>* reference = reference_trajectory(n, 1);
  const std::vector<Eigen::VectorXd>* fine_reference = reference_trajectory(n, 16);
  SheetRun run;
  for (auto _ : bench) {
    run = run_sheet(cloth, params, 1, reference != nullptr);
    if (!run.finite) {
      bench.SkipWithError("non-finite state");
      return;
    }
    bench.SetIterationTime(run.wall_s);
  }
  const State& state = run.last;
  double lowest_m = 0.0;
  for (int p = 0; p < model.particle_count(); ++p)
    lowest_m = std::min(lowest_m, state.x[3 * p + 2]);
  std::vector<double> stretches;  // of the structural springs
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.kind[s] != SpringKind::structural) continue;
    const double length_m =
        (state.x.segment<3>(3 * model.springs(s, 0)) - state.x.segment<3>(3 * model.springs(s, 1)))
            .norm();
    stretches.push_back(length_m / model.rest_length[s] - 1.0);
  }
  std::sort(stretches.begin(), stretches.end());
  bench.counters["lowest_m"] = lowest_m;
  bench.counters["median_stretch_pct"] = 100.0 * stretches[stretches.size() / 2];
  bench.counters["p90_stretch_pct"] = 100.0 * stretches[stretches.size() * 9 / 10];
  bench.counters["max_stretch_pct"] = 100.0 * stretches.back();
  bench.counters["ms_per_frame"] = 1e3 * run.wall_s / sheet_frames;
  bench.counters["iterations_per_step"] = static_cast<double>(run.iterations) / sheet_frames;
  bench.counters["preconditioner_solves_per_step"] =
      static_cast<double>(run.preconditioner_solves) / sheet_frames;
  bench.counters["unconverged"] = run.unconverged;
  bench.counters["particles"] = model.particle_count();
  // gaps to the converged trajectory at h and at h/16 (-1: no reference at this size)
  const auto gap = [&](const std::vector<Eigen::VectorXd>* to) {
    return to != nullptr ? trajectory_gap_pct(run.frames, *to) : std::make_pair(-1.0, -1.0);
  };
  std::tie(bench.counters["gap_mean_pct"], bench.counters["gap_max_pct"]) = gap(reference);
  std::tie(bench.counters["gap_h16_mean_pct"], bench.counters["gap_h16_max_pct"]) =
      gap(fine_reference);
}

void sheet_sizes(benchmark::internal::Benchmark* b) {
  b->Arg(41)->Arg(81)->Arg(128)->Arg(256)->Arg(512);
  b->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
}

// implicit Euler's conjugate gradient hits its cap on most steps from 81 x 81 on (and 128 x 128
// takes half an hour): the two smaller sheets only
BENCHMARK_CAPTURE(BM_HangingSheet, implicit_euler, Method{Integrator::implicit_euler})
    ->Arg(41)
    ->Arg(81)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_HangingSheet, pd_direct, Method{Integrator::projective_dynamics})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, pd_colored_gauss_seidel,
                  Method{Integrator::projective_dynamics, PdGlobalSolver::colored_gauss_seidel})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, newton, Method{Integrator::newton})->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, newton_pd_matrix,  // preconditioned by the PD matrix
                  Method{Integrator::newton, PdGlobalSolver::direct, 0.0,
                         NewtonPreconditioner::pd_matrix})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, newton_tight,  // tolerance 3e-3
                  Method{Integrator::newton, PdGlobalSolver::direct, 3e-3})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, quasi_newton, Method{Integrator::quasi_newton})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, quasi_newton_tight,  // tolerance 1e-3
                  Method{Integrator::quasi_newton, PdGlobalSolver::direct, 1e-3})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, quasi_newton_multigrid,  // H_0 by V-cycles of the PD matrix
                  Method{Integrator::quasi_newton, PdGlobalSolver::direct, 0.0,
                         NewtonPreconditioner::multigrid, QuasiNewtonInitialHessian::pd_multigrid})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, quasi_newton_multigrid_tight,  // and tolerance 1e-3
                  Method{Integrator::quasi_newton, PdGlobalSolver::direct, 1e-3,
                         NewtonPreconditioner::multigrid, QuasiNewtonInitialHessian::pd_multigrid})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, quasi_newton_gradient,  // gradient_reduction 0.1
                  Method{Integrator::quasi_newton, PdGlobalSolver::direct, 0.0,
                         NewtonPreconditioner::multigrid, QuasiNewtonInitialHessian::pd_matrix,
                         0.1})
    ->Apply(sheet_sizes);
BENCHMARK_CAPTURE(BM_HangingSheet, quasi_newton_multigrid_gradient,  // V-cycle, reduction 0.1
                  Method{Integrator::quasi_newton, PdGlobalSolver::direct, 0.0,
                         NewtonPreconditioner::multigrid, QuasiNewtonInitialHessian::pd_multigrid,
                         0.1})
    ->Apply(sheet_sizes);

/// The demos' settings before issue 16, which the others are compared against.
const std::vector<std::string> todays_settings = {"simulation.integrator=\"implicit_euler\"",
                                                  "simulation.substeps=10"};

/// The converged motion at one step per frame: backward Euler solved by Newton to 1e-4.
const std::vector<std::string> converged_settings = {
    "simulation.integrator=\"newton\"", "simulation.substeps=1", "simulation.newton.tolerance=1e-4",
    "simulation.newton.max_iterations=100", "simulation.newton.cg_max_iterations=1000"};

/// The converged motion of a scene with tears or obstacles: both are resolved after each step,
/// outside the minimisation (tears are checked once per step, at most max_tears_per_step; an
/// obstacle's contacts are projected and their friction applied after it), so one converged
/// step per frame is not the scene's converged motion; ten times smaller steps than today's are
/// (implicit Euler and Newton tear the same there, docs/benchmarks.md).
const std::vector<std::string> small_step_settings = {"simulation.integrator=\"implicit_euler\"",
                                                      "simulation.substeps=100"};

/// The settings of `scenario_file`'s converged motion: small_step_settings where it tears or
/// meets obstacles.
const std::vector<std::string>& converged_settings_of(const std::string& scenario_file) {
  // TISSU_DEMO_REFERENCE="key=value ...": another reference for every demo, e.g. the penalty at
  // 100 quasi-Newton steps per frame (implicit Euler's projection after each step is not
  // converged on the tearing ball at 100 steps, docs/benchmarks.md)
  static const std::vector<std::string> chosen = bench::environment_words("TISSU_DEMO_REFERENCE");
  if (!chosen.empty()) return chosen;
  const Scenario scenario = load_scenario(TISSU_DATA_DIR "/scenarios/" + scenario_file, {});
  const bool after_step = scenario.tearing.enabled || !scenario.solver.obstacles.empty();
  return after_step ? small_step_settings : converged_settings;
}

/// The reference runs, by settings (todays_settings or converged_settings_of()) and scenario file.
std::map<std::vector<std::string>, std::map<std::string, bench::RecordedRun>>& reference_runs() {
  static std::map<std::vector<std::string>, std::map<std::string, bench::RecordedRun>> runs;
  return runs;
}

/// The run of `scenario_file` with the reference `settings`, from its benchmark if it ran first,
/// else run here once and kept.
const bench::RecordedRun& reference_run(const std::vector<std::string>& settings,
                                        const std::string& scenario_file) {
  std::map<std::string, bench::RecordedRun>& runs = reference_runs()[settings];
  auto found = runs.find(scenario_file);
  if (found == runs.end()) {
    found = runs.emplace(scenario_file, bench::run_recorded(scenario_file, settings)).first;
  }
  return found->second;
}

void BM_Demo(benchmark::State& state, const std::string& scenario_file,
             const std::vector<std::string>& overrides) {
  bench::RecordedRun run;
  for (auto _ : state) {
    run = bench::run_recorded(scenario_file, overrides);
    state.SetIterationTime(run.wall_s);
  }
  const std::vector<std::string>& converged = converged_settings_of(scenario_file);
  if (overrides == todays_settings || overrides == converged) {
    reference_runs()[overrides][scenario_file] = run;  // the others' reference
  }
  const bench::RecordedRun& today = reference_run(todays_settings, scenario_file);
  int unconverged = 0, tears = 0;
  for (const FrameStats& row : run.frames) {
    unconverged += row.unconverged_steps;
    tears += row.tears;
  }
  const bench::ShapeGap gap = bench::shape_gap(run, today);
  state.counters["wall_s_per_sim_s"] = run.wall_s / run.simulated_s;
  state.counters["today_wall_s_per_sim_s"] = today.wall_s / today.simulated_s;
  state.counters["mean_gap_pct"] = gap.mean_pct;
  state.counters["max_gap_pct"] = gap.max_pct;
  state.counters["unconverged"] = unconverged;
  state.counters["tears"] = tears;
  state.counters["pieces"] = run.frames.back().pieces;
  if (references_wanted()) {
    const bench::ShapeGap converged_gap =
        bench::shape_gap(run, reference_run(converged, scenario_file));
    state.counters["converged_gap_mean_pct"] = converged_gap.mean_pct;
    state.counters["converged_gap_max_pct"] = converged_gap.max_pct;
    state.counters["converged_surface_gap_mean_pct"] = converged_gap.surface_mean_pct;
  }
}

#define TISSU_DEMO(scenario, config, ...)                                         \
  BENCHMARK_CAPTURE(BM_Demo, scenario##_##config, std::string(#scenario ".json"), \
                    std::vector<std::string>{__VA_ARGS__})                        \
      ->Iterations(1)                                                             \
      ->UseManualTime()                                                           \
      ->Unit(benchmark::kSecond)

/// Demo/<scenario>_<integrator>_x<substeps>: the integrator at that many steps per frame, the
/// obstacles only after each step (the penalty off, whatever the scenario sets: the demos that
/// now set it are compared with themselves as they were).
#define TISSU_DEMO_STEPS(scenario, integrator, substeps)                                      \
  TISSU_DEMO(scenario, integrator##_x##substeps, "simulation.integrator=\"" #integrator "\"", \
             "simulation.substeps=" #substeps, "simulation.obstacle_penalty=0")

TISSU_DEMO_STEPS(curtain, implicit_euler, 10);
TISSU_DEMO(curtain, newton_converged_x1, converged_settings);
TISSU_DEMO_STEPS(curtain, quasi_newton, 1);
TISSU_DEMO(curtain, quasi_newton_tight_x1, "simulation.integrator=\"quasi_newton\"",
           "simulation.substeps=1", "simulation.quasi_newton.tolerance=1e-3");
TISSU_DEMO_STEPS(curtain, newton, 1);
TISSU_DEMO(curtain, pd_direct_x1, "simulation.integrator=\"projective_dynamics\"",
           "simulation.substeps=1");
/// Demo/<scenario>_<integrator>_penalty_x<substeps>: the same with the obstacles held inside the
/// minimisation too (simulation.obstacle_penalty = 100).
#define TISSU_DEMO_PENALTY(scenario, integrator, substeps)                                  \
  TISSU_DEMO(scenario, integrator##_penalty_x##substeps,                                    \
             "simulation.integrator=\"" #integrator "\"", "simulation.substeps=" #substeps, \
             "simulation.obstacle_penalty=100")

TISSU_DEMO_STEPS(drape, implicit_euler, 10);
TISSU_DEMO(drape, implicit_euler_x100, small_step_settings);
TISSU_DEMO_STEPS(drape, implicit_euler, 20);
TISSU_DEMO_STEPS(drape, quasi_newton, 20);
TISSU_DEMO_STEPS(drape, newton, 20);
TISSU_DEMO_STEPS(drape, quasi_newton, 10);
TISSU_DEMO_STEPS(drape, quasi_newton, 1);
TISSU_DEMO_STEPS(drape, newton, 1);
TISSU_DEMO_STEPS(drape, newton, 10);
TISSU_DEMO_PENALTY(drape, newton, 1);
TISSU_DEMO_PENALTY(drape, newton, 2);
TISSU_DEMO_PENALTY(drape, newton, 4);
TISSU_DEMO_PENALTY(drape, quasi_newton, 1);
TISSU_DEMO_PENALTY(drape, quasi_newton, 2);
TISSU_DEMO_PENALTY(drape, quasi_newton, 4);
TISSU_DEMO_STEPS(tearing, implicit_euler, 10);
TISSU_DEMO(tearing, implicit_euler_x100, small_step_settings);
TISSU_DEMO_STEPS(tearing, quasi_newton, 10);
TISSU_DEMO_STEPS(tearing, quasi_newton, 20);
TISSU_DEMO_STEPS(tearing, quasi_newton, 30);
TISSU_DEMO_STEPS(tearing, newton, 10);
TISSU_DEMO_STEPS(tearing, newton, 20);
TISSU_DEMO_STEPS(tearing_ball, implicit_euler, 10);
TISSU_DEMO(tearing_ball, implicit_euler_x100, small_step_settings);
TISSU_DEMO_STEPS(tearing_ball, quasi_newton, 10);
TISSU_DEMO_STEPS(tearing_ball, quasi_newton, 20);
TISSU_DEMO_STEPS(tearing_ball, implicit_euler, 30);
TISSU_DEMO_PENALTY(tearing_ball, quasi_newton, 10);
TISSU_DEMO(skirt_walk, implicit_euler_x100, small_step_settings);
TISSU_DEMO_STEPS(skirt_walk, quasi_newton, 2);  // the demo before
TISSU_DEMO_PENALTY(skirt_walk, quasi_newton, 1);
TISSU_DEMO_PENALTY(skirt_walk, quasi_newton, 2);
TISSU_DEMO_PENALTY(skirt_walk, quasi_newton, 4);
TISSU_DEMO(tshirt_arms, implicit_euler_x100, small_step_settings);
TISSU_DEMO_STEPS(tshirt_arms, quasi_newton, 8);  // the demo before
TISSU_DEMO_PENALTY(tshirt_arms, quasi_newton, 2);
TISSU_DEMO_PENALTY(tshirt_arms, quasi_newton, 4);
TISSU_DEMO_PENALTY(tshirt_arms, quasi_newton, 8);

}  // namespace
}  // namespace tissu

BENCHMARK_MAIN();
