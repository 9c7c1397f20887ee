// Adaptive refinement against uniform meshes, on three scenes: the curtain (curtain.json), a sheet
// draped on a ball (drape_adaptive.json) and a flag in gusty wind (flag.json). Each adaptive scene
// runs against its uniform fine twin, at the finest level it may reach or finer
// (curtain_uniform.json, drape.json, flag_uniform.json), against the coarse mesh it starts from
// (adaptive.enabled=false) and against the uniform mesh one level finer than that (twice the cells
// each way, bending springs scaled as docs/scenario.md "Stiffness across levels" says). Reports
// wall time per simulated second (remeshing and recompiling included), particle counts, and how
// far each shape is from the uniform fine one at the same material points (mean_gap_pct,
// max_gap_pct) and as a surface, whichever material point lies where (surface_gap_*: a fold that
// fell the other way counts by how far the surface moved, not by how far its points travelled).
//
// Two floors under the gaps, from the uniform fine run again:
// - the noise floor, with gravity changed by one part in 10^11: how far the fine run is from
//   itself under a change far below any physical meaning (contact, buckling and the solvers'
//   tolerances amplify it); a gap below it says nothing;
// - the time-step floor, at half its time step: how far the fine run is from its own motion's
//   time discretisation; a mesh's gap below it is smaller than the reference's own error.
//
// Results and the machine: docs/benchmarks.md; scripts/plot_adaptive.sh plots gap against time.
// To try other settings, put --set overrides for the adaptive runs in TISSU_ADAPTIVE_SET,
// separated by spaces, e.g.
//   TISSU_ADAPTIVE_SET="adaptive.curvature=3 adaptive.every=2" adaptive_bench
// and to compare against a reference nearer its converged motion, TISSU_REFERENCE_STEPS=k runs
// the uniform fine mesh and its floors at k times their steps per frame, and adds the fine mesh
// at the compared runs' steps (fine_scene_steps) to the runs compared with it.
// TISSU_COMPARED_STEPS=j runs the compared meshes (adaptive, uniform mid and coarse, and that fine
// mesh) at j times their scenario's steps: speed-ups at equal steps, against the same reference.
// TISSU_FRAMES=n makes every run n frames long.
//
// The flag follows no reference instant by instant (gusty wind on flapping cloth amplifies any
// change: its noise floor is 5 %), so the runs are also compared by the statistics of their
// motions from 1 s on (bench::motion_statistics_gap; every scene has them, the flag is judged by
// them): the gap between the time-averaged shapes
// (mean_shape_gap_pct), between how far each material point flaps about its mean
// (spread_gap_pct), and the ratio of their mean spreads (spread_ratio).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>

#include "bench/recorded_run.hpp"

namespace tissu {
namespace {

struct Scene {
  std::string adaptive_file;
  std::string uniform_file;
};

const std::map<std::string, Scene>& scenes() {
  static const std::map<std::string, Scene> all{
      {"curtain", {"curtain.json", "curtain_uniform.json"}},
      {"drape", {"drape_adaptive.json", "drape.json"}},
      {"flag", {"flag.json", "flag_uniform.json"}},
  };
  return all;
}

/// The integer >= 1 in the environment variable `name`, 1 if unset.
int step_factor(const char* name) {
  const char* text = std::getenv(name);
  const int factor = text ? std::atoi(text) : 1;
  if (factor < 1) throw std::runtime_error(std::string(name) + ": expected an integer >= 1");
  return factor;
}

/// TISSU_REFERENCE_STEPS=k: the uniform fine runs (the reference and its two floors) take k
/// times their scenario's steps per frame, for a reference nearer its converged motion.
int reference_step_factor() {
  return step_factor("TISSU_REFERENCE_STEPS");
}

/// TISSU_COMPARED_STEPS=j: the runs compared with the reference take j times their scenario's
/// steps per frame.
int compared_step_factor() {
  return step_factor("TISSU_COMPARED_STEPS");
}

/// The overrides that run `file` at `factor` times its steps per frame (checked against the step
/// limits as any override is).
std::vector<std::string> more_steps(const std::string& file, int factor) {
  if (factor == 1) return {};
  const int substeps = load_scenario(TISSU_DATA_DIR "/scenarios/" + file, {}).substeps;
  return {"simulation.substeps=" + std::to_string(factor * substeps)};
}

/// TISSU_FRAMES=n: every run simulates n frames instead of its scenario's, for motion statistics
/// over a longer window (the flag's).
std::vector<std::string> frame_count_override() {
  const char* text = std::getenv("TISSU_FRAMES");
  if (text == nullptr) return {};
  if (std::atoi(text) < 1) throw std::runtime_error("TISSU_FRAMES: expected an integer >= 1");
  return {"simulation.frames=" + std::to_string(std::atoi(text))};
}

/// The overrides of every run of `file` at `factor` times its steps per frame.
std::vector<std::string> run_overrides(const std::string& file, int factor) {
  std::vector<std::string> overrides = more_steps(file, factor);
  for (std::string& word : frame_count_override()) overrides.push_back(std::move(word));
  return overrides;
}

/// The uniform fine runs by scene, kept by their benchmark.
std::map<std::string, bench::RecordedRun>& fine_runs() {
  static std::map<std::string, bench::RecordedRun> runs;
  return runs;
}

/// The uniform fine run of `scene`, from its benchmark if it ran first, else from a run of its own.
const bench::RecordedRun& fine_run(const std::string& scene) {
  bench::RecordedRun& run = fine_runs()[scene];
  const std::string& file = scenes().at(scene).uniform_file;
  if (run.shapes.empty())
    run = bench::run_recorded(file, run_overrides(file, reference_step_factor()));
  return run;
}

enum class Mesh {
  uniform_fine,
  fine_nudged,
  fine_half_step,
  fine_scene_steps,  ///< the fine mesh at the compared runs' steps, when not the reference's
  adaptive,
  uniform_mid,
  uniform_coarse
};

/// The noise floor's change to gravity, relative.
constexpr double gravity_nudge = 1e-11;

/// The motion statistics are taken from then on (s): after the flag has left its flat start and
/// the first gust has reached it, after the drape has come down on the ball.
constexpr double statistics_from_s = 1.0;

/// The grid cloth of `scenario` with twice the cells each way, one level of refinement (two
/// bisections) finer: the same pins (a side pinned at every n-th vertex, n > 1, at every 2n-th;
/// one pinned whole stays whole, as refinement pins a clamped edge's midpoint), bending springs 4
/// times as stiff per bisection, as refinement makes them.
void one_level_finer(Scenario& scenario) {
  if (!scenario.cloth.grid) throw std::runtime_error(scenario.name + ": not a grid cloth");
  scenario.cloth.grid->cells_u *= 2;
  scenario.cloth.grid->cells_v *= 2;
  for (PinSelector& pins : scenario.pins) {
    if (pins.kind == PinSelector::Kind::side && pins.every > 1) pins.every *= 2;
    // vertex ids change with the grid, and a box would take the finer grid's new vertices too
    if (pins.kind == PinSelector::Kind::indices || pins.kind == PinSelector::Kind::box) {
      throw std::runtime_error(scenario.name + ": pins by vertex index or box");
    }
  }
  if (!scenario.springs.material) {  // a material's bending springs follow their own hinges
    scenario.springs.bending.stiffness *= 16.0;
    scenario.springs.bending.damping *= 16.0;
  }
}

void BM_Adaptivity(benchmark::State& state, const std::string& scene, Mesh mesh) {
  const Scene& files = scenes().at(scene);
  const bool reference_or_floor =
      mesh == Mesh::uniform_fine || mesh == Mesh::fine_nudged || mesh == Mesh::fine_half_step;
  const bool fine = reference_or_floor || mesh == Mesh::fine_scene_steps;
  const std::string& file = fine ? files.uniform_file : files.adaptive_file;
  const int step_factor = reference_or_floor
                              ? reference_step_factor() * (mesh == Mesh::fine_half_step ? 2 : 1)
                              : compared_step_factor();
  std::vector<std::string> overrides = run_overrides(file, step_factor);
  std::function<void(Scenario&)> edit;
  if (mesh == Mesh::adaptive) {  // after the steps: TISSU_ADAPTIVE_SET has the last word
    for (std::string& word : bench::environment_words("TISSU_ADAPTIVE_SET")) {
      overrides.push_back(std::move(word));
    }
  }
  if (mesh == Mesh::uniform_mid || mesh == Mesh::uniform_coarse) {
    overrides.push_back("adaptive.enabled=false");
  }
  if (mesh == Mesh::uniform_mid) edit = one_level_finer;
  if (mesh == Mesh::fine_nudged) {
    edit = [](Scenario& s) { s.solver.environment.gravity *= 1.0 + gravity_nudge; };
  }
  bench::RecordedRun run;
  for (auto _ : state) {
    run = bench::run_recorded(file, overrides, edit);
    state.SetIterationTime(run.wall_s);
  }
  if (mesh == Mesh::uniform_fine) fine_runs()[scene] = run;
  double particles_summed = 0.0, step_ms = 0.0;  // over the frames
  int max_particles = 0;
  long iterations = 0;
  for (const FrameStats& row : run.frames) {
    particles_summed += static_cast<double>(row.particles);
    max_particles = std::max(max_particles, row.particles);
    iterations += row.solver_iterations;
    step_ms += row.step_ms;
  }
  const double mean_particles = particles_summed / static_cast<double>(run.frames.size());
  const double stepped_frames = static_cast<double>(run.frames.size() - 1);
  const bench::ShapeGap gap = bench::shape_gap(run, fine_run(scene));
  state.counters["wall_s_per_sim_s"] = run.wall_s / run.simulated_s;
  state.counters["mean_particles"] = mean_particles;
  state.counters["max_particles"] = max_particles;
  // the integrator's iterations per frame, and the steps' wall time per particle and frame: what
  // a particle costs on this mesh (issue 19's "cost per particle")
  state.counters["solver_iterations_per_frame"] = static_cast<double>(iterations) / stepped_frames;
  state.counters["step_us_per_particle_frame"] = 1e3 * step_ms / particles_summed;
  state.counters["mean_gap_pct"] = gap.mean_pct;
  state.counters["max_gap_pct"] = gap.max_pct;
  state.counters["surface_gap_mean_pct"] = gap.surface_mean_pct;
  state.counters["surface_gap_max_pct"] = gap.surface_max_pct;
  // on every scene, so that each run has the same counters (the CSV reporter aborts otherwise);
  // the flag's runs follow no reference instant by instant, and are judged by these
  const bench::MotionStatisticsGap statistics =
      bench::motion_statistics_gap(run, fine_run(scene), statistics_from_s);
  state.counters["mean_shape_gap_pct"] = statistics.mean_shape_pct;
  state.counters["spread_gap_pct"] = statistics.spread_pct;
  state.counters["spread_ratio"] = statistics.spread_ratio;
}

// per scene, the fine run first, so that the others compare against its shapes without running it
// again
void register_all() {
  for (const auto& [scene, files] : scenes()) {
    for (const auto& [name, mesh] :
         {std::pair{"uniform_fine", Mesh::uniform_fine},
          std::pair{"fine_nudged", Mesh::fine_nudged},
          std::pair{"fine_half_step", Mesh::fine_half_step}, std::pair{"adaptive", Mesh::adaptive},
          std::pair{"uniform_mid", Mesh::uniform_mid},
          std::pair{"uniform_coarse", Mesh::uniform_coarse},
          std::pair{"fine_scene_steps", Mesh::fine_scene_steps}}) {
      // at the reference's steps, the fine mesh is the reference itself
      if (mesh == Mesh::fine_scene_steps && reference_step_factor() == compared_step_factor())
        continue;
      benchmark::RegisterBenchmark(("BM_Adaptivity/" + scene + "/" + name).c_str(), BM_Adaptivity,
                                   scene, mesh)
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kSecond);
    }
  }
}

}  // namespace
}  // namespace tissu

int main(int argc, char** argv) {
  tissu::register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
