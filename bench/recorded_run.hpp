#pragma once
// A shipped scenario run for a benchmark: its wall time, every frame's statistics and its shape
// every second, and how far its shapes are from another run's (adaptive_bench, integrator_bench).

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "lib/shape_distance.hpp"
#include "lib/simulation.hpp"

namespace tissu::bench {

inline constexpr int frames_between_shape_samples = 30;  // 1 s at the demos' 30 frames/s
inline constexpr int frames_between_motion_samples = 3;  // 10 per second at 30 frames/s

struct RecordedRun {
  double wall_s = 0.0;
  double simulated_s = 0.0;
  double frame_rate_hz = 0.0;
  std::vector<FrameStats> frames;       ///< frame 0 too
  std::vector<MaterialSurface> shapes;  ///< every frames_between_shape_samples frames
  std::vector<MaterialSurface> motion;  ///< every frames_between_motion_samples frames
};

/// The directory the runs of this process write their stats and point caches to, one per process
/// so that benchmarks run side by side do not remove each other's files (tissu_bench_<pid> in the
/// temporary directory); removed when the process exits.
inline const std::filesystem::path& run_directory() {
  struct Directory {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("tissu_bench_" + std::to_string(::getpid()));
    ~Directory() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Directory directory;
  return directory.path;
}

/// The words of the environment variable `name` (none when it is unset), e.g. `--set` overrides
/// separated by spaces: TISSU_ADAPTIVE_SET, TISSU_DEMO_REFERENCE.
inline std::vector<std::string> environment_words(const char* name) {
  const char* text = std::getenv(name);
  std::istringstream words(text ? text : "");
  std::vector<std::string> found;
  for (std::string word; words >> word;) found.push_back(word);
  return found;
}

/// Runs data/scenarios/<scenario_file> with `overrides`, then `edit` when given, without images or
/// meshes; throws if the run fails.
inline RecordedRun run_recorded(const std::string& scenario_file,
                                const std::vector<std::string>& overrides,
                                const std::function<void(Scenario&)>& edit = {}) {
  std::vector<std::string> quiet = overrides;
  quiet.insert(quiet.end(), {"render.enabled=false", "output.meshes=false"});
  Scenario scenario = load_scenario(TISSU_DATA_DIR "/scenarios/" + scenario_file, quiet);
  if (edit) edit(scenario);
  RecordedRun run;
  RunOptions options;
  options.output_dir = run_directory();
  options.on_frame = [&](const FrameStats& row) { run.frames.push_back(row); };
  options.on_surface = [&](int frame, const MaterialSurface& surface) {
    if (frame % frames_between_shape_samples == 0) run.shapes.push_back(surface);
    if (frame % frames_between_motion_samples == 0) run.motion.push_back(surface);
  };
  const auto start = std::chrono::steady_clock::now();
  const RunResult result = run_scenario(scenario, options);
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.ok) throw std::runtime_error(result.failure);
  run.simulated_s = scenario.frames / scenario.frame_rate;
  run.frame_rate_hz = scenario.frame_rate;
  return run;
}

/// Over the sampled instants: the mean of the mean distance between the same material points of
/// `run` and `reference`, and the largest distance seen, as percentages of the cloth's rest
/// diagonal; and the same for the distance between the two surfaces, whichever material point
/// lies where (surface_distance_between(): a fold that fell the other way counts by how far the
/// surface moved).
struct ShapeGap {
  double mean_pct = 0.0;
  double max_pct = 0.0;
  double surface_mean_pct = 0.0;
  double surface_max_pct = 0.0;
};

inline ShapeGap shape_gap(const RecordedRun& run, const RecordedRun& reference) {
  double mean_m = 0.0, max_m = 0.0, surface_mean_m = 0.0, surface_max_m = 0.0;
  for (std::size_t k = 0; k < run.shapes.size(); ++k) {
    const ShapeDistance d = material_point_distance(run.shapes[k], reference.shapes.at(k));
    mean_m += d.mean_m / run.shapes.size();
    max_m = std::max(max_m, d.max_m);
    const ShapeDistance s =
        surface_distance_between(run.shapes[k].current, reference.shapes.at(k).current);
    surface_mean_m += s.mean_m / run.shapes.size();
    surface_max_m = std::max(surface_max_m, s.max_m);
  }
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& X : reference.shapes.front().rest_m) box.extend(X);
  const double percent_per_m = 100.0 / box.diagonal().norm();
  return {percent_per_m * mean_m, percent_per_m * max_m, percent_per_m * surface_mean_m,
          percent_per_m * surface_max_m};
}

/// How the statistics of two runs' motions differ, for a motion that no run can follow instant by
/// instant (a flag in gusty wind: a change of gravity in its 11th digit moves it by 5 %). Over
/// the motion samples from `from_s` on, each material point of the reference (its vertices) has
/// a mean position and a spread about it (the root mean square distance from that mean); the
/// gaps are means over the points, in % of the cloth's rest diagonal:
/// - `mean_shape_pct`: between the two runs' mean positions (the time-averaged shape);
/// - `spread_pct`: between the two runs' spreads (how far each point flaps);
/// - `spread_ratio`: the run's mean spread over the reference's (dimensionless).
struct MotionStatisticsGap {
  double mean_shape_pct = 0.0;
  double spread_pct = 0.0;
  double spread_ratio = 0.0;
};

inline MotionStatisticsGap motion_statistics_gap(const RecordedRun& run,
                                                 const RecordedRun& reference, double from_s) {
  const auto first = static_cast<std::size_t>(
      std::ceil(from_s * reference.frame_rate_hz / frames_between_motion_samples - 1e-9));
  const std::size_t samples = std::min(run.motion.size(), reference.motion.size());
  if (first >= samples)
    throw std::invalid_argument("motion_statistics_gap: no sample after from_s");
  const std::vector<Eigen::Vector3d>& points = reference.motion.front().rest_m;
  const std::size_t count = points.size();
  // per point: the sums of x and of |x|^2 over the samples, for each run
  std::vector<Eigen::Vector3d> sum_run(count, Eigen::Vector3d::Zero()), sum_ref = sum_run;
  std::vector<double> square_run(count, 0.0), square_ref(count, 0.0);
  for (std::size_t k = first; k < samples; ++k) {
    if (reference.motion[k].current.vertices.size() != count) {
      throw std::invalid_argument("motion_statistics_gap: the reference's mesh changed");
    }
    const std::vector<Eigen::Vector3d> here = material_point_positions(run.motion[k], points);
    for (std::size_t i = 0; i < count; ++i) {
      const Eigen::Vector3d& x_ref = reference.motion[k].current.vertices[i];
      sum_run[i] += here[i];
      sum_ref[i] += x_ref;
      square_run[i] += here[i].squaredNorm();
      square_ref[i] += x_ref.squaredNorm();
    }
  }
  const double n = static_cast<double>(samples - first);
  double mean_gap_m = 0.0, spread_gap_m = 0.0, spread_run_m = 0.0, spread_ref_m = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d mean_run = sum_run[i] / n, mean_ref = sum_ref[i] / n;
    // spread^2 = mean |x|^2 - |mean x|^2 (clamped at 0 against round-off)
    const double spread_run = std::sqrt(std::max(0.0, square_run[i] / n - mean_run.squaredNorm()));
    const double spread_ref = std::sqrt(std::max(0.0, square_ref[i] / n - mean_ref.squaredNorm()));
    mean_gap_m += (mean_run - mean_ref).norm() / count;
    spread_gap_m += std::abs(spread_run - spread_ref) / count;
    spread_run_m += spread_run / count;
    spread_ref_m += spread_ref / count;
  }
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& X : points) box.extend(X);
  const double percent_per_m = 100.0 / box.diagonal().norm();
  return {percent_per_m * mean_gap_m, percent_per_m * spread_gap_m,
          spread_ref_m > 0.0 ? spread_run_m / spread_ref_m : 0.0};
}

}  // namespace tissu::bench
