// The adaptive curtain (data/scenarios/curtain.json) against the same curtain on uniform grids:
// the finest level it reaches (curtain_uniform.json) and the level it starts from. Reports wall
// time per simulated second, particle counts, and how far each shape is from the uniform fine
// one at the same material points. Results and the machine: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "lib/simulation.hpp"

namespace tissu {
namespace {

constexpr int frames_between_shape_samples = 30;  // 1 s of the 30 frame/s curtain

struct CurtainRun {
  double wall_s = 0.0;
  double simulated_s = 0.0;
  double mean_particles = 0.0;
  int max_particles = 0;
  std::vector<MaterialSurface> shapes;  ///< every frames_between_shape_samples frames
};

CurtainRun run_curtain(const std::string& scenario_file,
                       const std::vector<std::string>& overrides) {
  std::vector<std::string> quiet = overrides;
  quiet.insert(quiet.end(), {"render.enabled=false", "output.meshes=false"});
  const Scenario scenario = load_scenario(TISSU_DATA_DIR "/scenarios/" + scenario_file, quiet);
  CurtainRun run;
  RunOptions options;
  options.output_dir = std::filesystem::temp_directory_path() / "tissu_adaptive_bench";
  options.on_frame = [&](const FrameStats& row) {
    run.mean_particles += row.particles;
    run.max_particles = std::max(run.max_particles, row.particles);
  };
  options.on_surface = [&](int frame, const MaterialSurface& surface) {
    if (frame % frames_between_shape_samples == 0) run.shapes.push_back(surface);
  };
  const auto start = std::chrono::steady_clock::now();
  const RunResult result = run_scenario(scenario, options);
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.ok) throw std::runtime_error(result.failure);
  run.simulated_s = scenario.frames / scenario.frame_rate;
  run.mean_particles /= scenario.frames + 1;
  return run;
}

/// The uniform fine run's shapes, from its benchmark if it ran first, else from a run of its own.
std::vector<MaterialSurface>& fine_shapes() {
  static std::vector<MaterialSurface> shapes;
  if (shapes.empty()) shapes = run_curtain("curtain_uniform.json", {}).shapes;
  return shapes;
}

double rest_diagonal_m(const MaterialSurface& s) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& X : s.rest_m) box.extend(X);
  return box.diagonal().norm();
}

void BM_Curtain(benchmark::State& bench, const std::string& scenario_file,
                const std::vector<std::string>& overrides) {
  CurtainRun run;
  for (auto _ : bench) {
    run = run_curtain(scenario_file, overrides);
    bench.SetIterationTime(run.wall_s);
  }
  if (scenario_file == "curtain_uniform.json") fine_shapes() = run.shapes;
  const std::vector<MaterialSurface>& fine = fine_shapes();
  // mean over the sampled instants of the mean distance to the fine shape, as a percentage of
  // the cloth's rest diagonal; and the largest distance seen
  double mean_gap_m = 0.0, max_gap_m = 0.0;
  for (std::size_t k = 0; k < run.shapes.size(); ++k) {
    const ShapeDistance d = material_point_distance(run.shapes[k], fine.at(k));
    mean_gap_m += d.mean_m / run.shapes.size();
    max_gap_m = std::max(max_gap_m, d.max_m);
  }
  const double size_m = rest_diagonal_m(fine.front());
  bench.counters["wall_s_per_sim_s"] = run.wall_s / run.simulated_s;
  bench.counters["mean_particles"] = run.mean_particles;
  bench.counters["max_particles"] = run.max_particles;
  bench.counters["mean_gap_pct"] = 100.0 * mean_gap_m / size_m;
  bench.counters["max_gap_pct"] = 100.0 * max_gap_m / size_m;
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
