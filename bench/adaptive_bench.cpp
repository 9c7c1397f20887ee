// The adaptive curtain (data/scenarios/curtain.json) against the same curtain on uniform grids:
// the finest level it reaches (curtain_uniform.json) and the level it starts from. Reports wall
// time per simulated second, particle counts, and how far each shape is from the uniform fine
// one at the same material points. Results and the machine: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "bench/recorded_run.hpp"

namespace tissu {
namespace {

/// The uniform fine run, from its benchmark if it ran first, else from a run of its own.
bench::RecordedRun& fine_run() {
  static bench::RecordedRun run;
  if (run.shapes.empty()) run = bench::run_recorded("curtain_uniform.json", {});
  return run;
}

void BM_Curtain(benchmark::State& state, const std::string& scenario_file,
                const std::vector<std::string>& overrides) {
  bench::RecordedRun run;
  for (auto _ : state) {
    run = bench::run_recorded(scenario_file, overrides);
    state.SetIterationTime(run.wall_s);
  }
  if (scenario_file == "curtain_uniform.json") fine_run() = run;
  double mean_particles = 0.0;
  int max_particles = 0;
  for (const FrameStats& row : run.frames) {
    mean_particles += static_cast<double>(row.particles) / run.frames.size();
    max_particles = std::max(max_particles, row.particles);
  }
  const bench::ShapeGap gap = bench::shape_gap(run, fine_run());
  state.counters["wall_s_per_sim_s"] = run.wall_s / run.simulated_s;
  state.counters["mean_particles"] = mean_particles;
  state.counters["max_particles"] = max_particles;
  state.counters["mean_gap_pct"] = gap.mean_pct;
  state.counters["max_gap_pct"] = gap.max_pct;
}

// the fine run first, so that the others compare against its shapes without running it again
BENCHMARK_CAPTURE(BM_Curtain, uniform_fine, std::string("curtain_uniform.json"),
                  std::vector<std::string>{})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_Curtain, adaptive, std::string("curtain.json"), std::vector<std::string>{})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_Curtain, uniform_coarse, std::string("curtain.json"),
                  std::vector<std::string>{"adaptive.enabled=false"})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond);

}  // namespace
}  // namespace tissu

BENCHMARK_MAIN();
