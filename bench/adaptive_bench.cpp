// Adaptive refinement against uniform meshes, on three scenes: the curtain (curtain.json), a sheet
// draped on a ball (drape_adaptive.json) and a flag in gusty wind (flag.json). Each adaptive scene
// runs against its uniform twin at the finest level it reaches (curtain_uniform.json, drape.json,
// flag_uniform.json) and against the coarse mesh it starts from (adaptive.enabled=false). Reports
// wall time per simulated second (remeshing and recompiling included), particle counts, and how
// far each shape is from the uniform fine one at the same material points. Results and the
// machine: docs/benchmarks.md. To try other settings, put
// --set overrides for the adaptive runs in TISSU_ADAPTIVE_SET, separated by spaces, e.g.
//   TISSU_ADAPTIVE_SET="adaptive.curvature=3 adaptive.every=2" adaptive_bench

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <sstream>
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

/// The uniform fine run of `scene`, from its benchmark if it ran first, else from a run of its own.
bench::RecordedRun& fine_run(const std::string& scene) {
  static std::map<std::string, bench::RecordedRun> runs;
  bench::RecordedRun& run = runs[scene];
  if (run.shapes.empty()) run = bench::run_recorded(scenes().at(scene).uniform_file, {});
  return run;
}

enum class Mesh { uniform_fine, adaptive, uniform_coarse };

/// The overrides of TISSU_ADAPTIVE_SET, for the adaptive runs.
std::vector<std::string> adaptive_overrides() {
  std::vector<std::string> overrides;
  const char* text = std::getenv("TISSU_ADAPTIVE_SET");
  std::istringstream words(text ? text : "");
  for (std::string word; words >> word;) overrides.push_back(word);
  return overrides;
}

void BM_Adaptivity(benchmark::State& state, const std::string& scene, Mesh mesh) {
  const Scene& files = scenes().at(scene);
  const std::string& file = mesh == Mesh::uniform_fine ? files.uniform_file : files.adaptive_file;
  std::vector<std::string> overrides;
  if (mesh == Mesh::adaptive) overrides = adaptive_overrides();
  if (mesh == Mesh::uniform_coarse) overrides.push_back("adaptive.enabled=false");
  bench::RecordedRun run;
  for (auto _ : state) {
    run = bench::run_recorded(file, overrides);
    state.SetIterationTime(run.wall_s);
  }
  if (mesh == Mesh::uniform_fine) fine_run(scene) = run;
  double mean_particles = 0.0;
  int max_particles = 0;
  for (const FrameStats& row : run.frames) {
    mean_particles += static_cast<double>(row.particles) / run.frames.size();
    max_particles = std::max(max_particles, row.particles);
  }
  const bench::ShapeGap gap = bench::shape_gap(run, fine_run(scene));
  state.counters["wall_s_per_sim_s"] = run.wall_s / run.simulated_s;
  state.counters["mean_particles"] = mean_particles;
  state.counters["max_particles"] = max_particles;
  state.counters["mean_gap_pct"] = gap.mean_pct;
  state.counters["max_gap_pct"] = gap.max_pct;
}

// per scene, the fine run first, so that the others compare against its shapes without running it
// again
void register_all() {
  for (const auto& [scene, files] : scenes()) {
    for (const auto& [name, mesh] :
         {std::pair{"uniform_fine", Mesh::uniform_fine}, std::pair{"adaptive", Mesh::adaptive},
          std::pair{"uniform_coarse", Mesh::uniform_coarse}}) {
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
