// Cloths tearing while they move: the driver tears after the steps that overstretch the cloth,
// cuts when a scripted cut is due, recompiles, and the mass stays put.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"
#include "tests/test_thread_count.hpp"

namespace tissu {
namespace {

/// A 0.2 m x 1 m strip in the x-z plane, 0.05 m cells, its ends pulled apart at 0.1 m/s each.
std::string pulled_strip(const std::string& tearing) {
  return R"({
  "cloth": { "grid": { "size": [0.2, 1.0], "resolution": [4, 20] },
             "density": 0.2,
             "springs": { "structural": { "stiffness": 500, "damping": 0.2 },
                          "bending": { "stiffness": 0.5, "damping": 0.01 } } },
  "pins": [ { "side": "bottom", "velocity": [0, 0, -0.1] }, { "side": "top", "velocity": [0, 0, 0.1] } ],
  "environment": { "gravity": [0, 0, 0], "air_damping": 0.2 },
  "tearing": )" +
         tearing +
         R"(,
  "simulation": { "frames": 45, "substeps": 10 },
  "output": { "meshes": false }
})";
}

struct TearingRun {
  RunResult result;
  std::vector<FrameStats> frames;
  MaterialSurface last;
};

TearingRun run(const std::string& scenario_json, const std::string& name) {
  TearingRun out;
  RunOptions options;
  options.output_dir = test::fresh_temp_dir(name);
  options.on_frame = [&](const FrameStats& s) { out.frames.push_back(s); };
  options.on_surface = [&](int, const MaterialSurface& surface) { out.last = surface; };
  out.result = run_scenario(parse_scenario(scenario_json, name + ".json"), options);
  return out;
}

/// Rest z of the particles that share their material coordinates with another: the crack's lips.
std::vector<double> crack_rest_heights(const MaterialSurface& surface) {
  std::map<std::tuple<double, double, double>, int> count;
  for (const Eigen::Vector3d& r : surface.rest_m) ++count[{r.x(), r.y(), r.z()}];
  std::vector<double> heights;
  for (const auto& [rest, n] : count) {
    if (n > 1) heights.push_back(std::get<2>(rest));
  }
  return heights;
}

void expect_mass_constant(const std::vector<FrameStats>& frames) {
  for (const FrameStats& f : frames) {
    EXPECT_NEAR(f.total_mass, frames.front().total_mass, 1e-12 * frames.front().total_mass)
        << "frame " << f.frame;
  }
}

TEST(TearingRun, APulledStripTearsAcrossItsWeakLineIntoExactlyTwoPieces) {
  const TearingRun r = run(pulled_strip(R"({ "strain": 0.2, "weak_regions": [
      { "line": [[-1, 0, 0.325], [1, 0, 0.325]], "width": 0.01, "factor": 0.5 } ] })"),
                           "weak_strip");
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  EXPECT_EQ(r.frames.front().pieces, 1);
  EXPECT_EQ(r.frames.back().pieces, 2);
  int tears = 0;
  for (const FrameStats& f : r.frames) tears += f.tears;
  EXPECT_GE(tears, 4);  // at least the strip's width
  expect_mass_constant(r.frames);
  const std::vector<double> heights = crack_rest_heights(r.last);
  EXPECT_FALSE(heights.empty());
  for (double z : heights) {
    EXPECT_TRUE(std::abs(z - 0.3) < 1e-9 || std::abs(z - 0.35) < 1e-9) << "crack at rest z = " << z;
  }
  // the pinned ends moved at their handles' speed
  const double t_s = r.frames.back().time;
  for (std::size_t i = 0; i < r.last.rest_m.size(); ++i) {
    if (std::abs(r.last.rest_m[i].z() - 1.0) < 1e-9) {
      EXPECT_NEAR(r.last.current.vertices[i].z(), 1.0 + 0.1 * t_s, 1e-9);
    }
  }
}

TEST(TearingRun, AStripWithoutAWeakLineStillTearsIntoTwoPieces) {
  const TearingRun r = run(pulled_strip(R"({ "strain": 0.15 })"), "plain_strip");
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  EXPECT_EQ(r.frames.back().pieces, 2);
  EXPECT_GT(r.frames.back().boundary_edges, r.frames.front().boundary_edges);
  expect_mass_constant(r.frames);
}

TEST(TearingRun, TearingWorksWithAdaptiveRefinementAndRefinedCrackTips) {
  std::string scenario = pulled_strip(R"({ "strain": 0.15, "tip_min_edge_length": 0.01 })");
  scenario.insert(
      scenario.rfind('}'),
      R"(, "adaptive": { "strain": 0.08, "min_edge_length": 0.01, "max_particles": 3000 })");
  const TearingRun r = run(scenario, "adaptive_strip");
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  EXPECT_EQ(r.frames.back().pieces, 2);
  int splits = 0, merges = 0;
  for (const FrameStats& f : r.frames) {
    splits += f.splits;
    merges += f.merges;
  }
  EXPECT_GT(splits, 0);
  EXPECT_GT(r.frames.back().particles, r.frames.front().particles);
  expect_mass_constant(r.frames);
}

TEST(TearingRun, BelowTheThresholdTheStripNeverTears) {
  const TearingRun r = run(pulled_strip(R"({ "strain": 2.0 })"), "strong_strip");
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  for (const FrameStats& f : r.frames) {
    EXPECT_EQ(f.tears, 0);
    EXPECT_EQ(f.pieces, 1);
  }
}

TEST(TearingRun, AScriptedCutSeparatesTheStripAtItsTime) {
  const TearingRun r = run(
      pulled_strip(R"({ "cuts": [ { "time": 0.5, "line": [[-0.1, 0, 0.5], [0.3, 0, 0.5]] } ] })"),
      "cut_strip");
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  for (const FrameStats& f : r.frames) {
    EXPECT_EQ(f.pieces, f.time < 0.5 - 1e-9 ? 1 : 2) << "t = " << f.time;
  }
  for (double z : crack_rest_heights(r.last)) EXPECT_NEAR(z, 0.5, 1e-9);
  expect_mass_constant(r.frames);
}

TEST(TearingRun, TheSameTearsForOneAndTwoThreads) {
  const std::string tearing = R"({ "strain": 0.15, "max_tears_per_step": 1 })";
  auto run_on = [&](int threads, const std::string& name) {
    const test::ScopedThreadCount count(threads);
    return run(pulled_strip(tearing), name);
  };
  const TearingRun one = run_on(1, "one_thread");
  const TearingRun two = run_on(2, "two_threads");
  ASSERT_EQ(one.frames.size(), two.frames.size());
  for (std::size_t f = 0; f < one.frames.size(); ++f) {
    EXPECT_EQ(one.frames[f].tears, two.frames[f].tears) << "frame " << f;
    EXPECT_EQ(one.frames[f].particles, two.frames[f].particles) << "frame " << f;
  }
  ASSERT_EQ(one.last.current.vertices.size(), two.last.current.vertices.size());
  for (std::size_t i = 0; i < one.last.current.vertices.size(); ++i) {
    EXPECT_EQ(one.last.current.vertices[i], two.last.current.vertices[i]) << "vertex " << i;
  }
}

TEST(TearingRun, StatsCountTearsPiecesAndBoundaryEdges) {
  const std::filesystem::path dir = test::fresh_temp_dir("tearing_stats");
  RunOptions options;
  options.output_dir = dir;
  run_scenario(parse_scenario(pulled_strip(R"({ "strain": 0.15 })"), "stats.json"), options);
  std::ifstream csv(dir / "stats.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find(",tears,pieces,boundary_edges"), std::string::npos) << header;
}

}  // namespace
}  // namespace tissu
