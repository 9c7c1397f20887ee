// A cloth refined while it moves: the driver recompiles after each refinement and mass stays put.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lib/scenario/scenario_error.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

const char* const waving_flag = R"({
  "cloth": { "grid": { "size": [1, 0.6], "resolution": [10, 6], "pleats": { "count": 2, "gathered_width": 0.8 } },
             "density": 0.2,
             "springs": { "structural": { "stiffness": 300, "damping": 0.2 },
                          "bending": { "stiffness": 1, "damping": 0.01 } } },
  "pins": [ { "side": "left" } ],
  "environment": { "air_damping": 0.2, "wind": { "velocity": [2, 1, 0], "gust_amplitude": 0.5, "gust_frequency": 1 } },
  "simulation": { "frames": 100, "substeps": 10 },
  "adaptive": { "curvature": 0.3, "strain": 0.05, "min_edge_length": 0.03, "max_particles": 400 },
  "output": { "meshes": false }
})";

struct Column {
  std::vector<double> total_mass_kg;
  std::vector<int> particles;
  int splits = 0;
};

Column read_stats(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  Column out;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    out.particles.push_back(std::stoi(cells.at(2)));
    out.total_mass_kg.push_back(std::stod(cells.at(6)));
    out.splits += std::stoi(cells.at(11));
  }
  return out;
}

TEST(AdaptiveRun, ThousandStepsOfRefinementKeepTheTotalMass) {
  const Scenario scenario = parse_scenario(waving_flag, "flag.json");
  RunOptions options;
  options.output_dir = test::fresh_temp_dir("adaptive_run");
  const RunResult result = run_scenario(scenario, options);
  ASSERT_TRUE(result.ok) << result.failure;

  const Column stats = read_stats(options.output_dir / "stats.csv");
  ASSERT_EQ(stats.total_mass_kg.size(), 101u);
  const double expected_kg = 0.2 * 1.0 * 0.6;
  for (std::size_t frame = 0; frame < stats.total_mass_kg.size(); ++frame) {
    EXPECT_NEAR(stats.total_mass_kg[frame], expected_kg, 1e-12 * expected_kg) << "frame " << frame;
  }
  EXPECT_GT(stats.splits, 0);
  EXPECT_GT(stats.particles.back(), stats.particles.front());
  EXPECT_LE(stats.particles.back(), 400);
}

TEST(AdaptiveRun, ScenarioChecksTheAdaptiveSection) {
  auto error_of = [](const std::vector<std::string>& overrides) -> std::string {
    try {
      parse_scenario(waving_flag, "flag.json", overrides);
    } catch (const ScenarioError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_THAT(
      error_of({"adaptive={}"}),
      HasSubstr("flag.json: adaptive.strain: expected a positive \"strain\" or \"curvature\""));
  EXPECT_THAT(error_of({"adaptive.curvature=4"}),
              HasSubstr("adaptive.curvature: expected a number between 0"));
  EXPECT_THAT(error_of({"cloth.grid.cells=quads"}),
              HasSubstr("adaptive: refinement needs a triangle cloth"));
  EXPECT_EQ(error_of({"adaptive.enabled=false", "cloth.grid.cells=quads"}), "no error");
}

}  // namespace
}  // namespace tissu
