// The run folder is a record: it holds one run only, and its scenario.json is the scenario as run,
// every default filled in, which runs again from anywhere to the same results.

#include "lib/run_folder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

/// A hanging sheet read from an OBJ beside the scenario, by a relative path.
const char* const sheet_scenario = R"({
  "cloth": { "mesh": { "file": "sheet.obj" }, "density": 0.2,
             "springs": { "structural": { "stiffness": 200, "damping": 0.1 },
                          "bending": { "stiffness": 0.5 } } },
  "pins": [ { "indices": [0, 2] } ],
  "simulation": { "frames": 4, "substeps": 5, "integrator": "projective_dynamics" },
  "output": { "mesh_format": "ply" }
})";

/// Two triangles of a 0.5 m square in the y = 0 plane, hanging from its top edge (vertices 0, 2).
const char* const sheet_obj = "v 0 0 0.5\nv 0 0 0\nv 0.5 0 0.5\nv 0.5 0 0\nf 1 2 4\nf 1 4 3\n";

fs::path write_sheet_scenario(const fs::path& dir) {
  write_text(dir / "sheet.obj", sheet_obj);
  write_text(dir / "sheet.json", sheet_scenario);
  return dir / "sheet.json";
}

/// stats.csv without its two wall-time columns (step_ms, collision_ms), which vary run to run.
std::vector<std::string> stats_without_timings(const fs::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    fields.erase(fields.begin() + 15);  // collision_ms
    fields.erase(fields.begin() + 9);   // step_ms
    std::string row;
    for (const std::string& field : fields) row += field + ",";
    rows.push_back(row);
  }
  return rows;
}

TEST(RunFolder, KnowsTheNamesOfTheFilesTissuWrites) {
  for (const char* name :
       {"stats.csv", "scenario.json", "run.json", "frame_00000.obj", "frame_12345.ply",
        "frame_00010.png", "last_good_frame_00004.obj", "last_good_frame_00004_step_03.ply",
        ".frame_00003.obj.tmp4242_7", ".stats.csv.tmp1_0"}) {
    EXPECT_TRUE(is_run_output_name(name)) << name;
  }
  for (const char* name : {"notes.txt", "frame_1.obj", "frame_00000.obj.bak", "my_stats.csv",
                           "scenario.json~", "frame_000001.obj", ".notes.txt.tmp1_0", "body.obj"}) {
    EXPECT_FALSE(is_run_output_name(name)) << name;
  }
}

TEST(RunFolder, ARerunLeavesOnlyItsOwnOutputsAndTheUsersFiles) {
  const fs::path dir = test::fresh_dir_for_this_test("run_folder");
  const Scenario scenario = load_scenario(write_sheet_scenario(dir));
  const fs::path out = dir / "out";
  RunOptions options;
  options.output_dir = out;
  ASSERT_TRUE(run_scenario(scenario, options).ok);
  ASSERT_TRUE(fs::exists(out / "frame_00004.ply"));
  write_text(out / "notes.txt", "mine");
  write_text(out / "sheet.mp4", "a video of the earlier run");
  fs::create_directory(out / "frames_i_kept");

  options.frames = 2;
  ASSERT_TRUE(run_scenario(scenario, options).ok);
  EXPECT_TRUE(fs::exists(out / "frame_00002.ply"));
  EXPECT_FALSE(fs::exists(out / "frame_00003.ply"));
  EXPECT_FALSE(fs::exists(out / "frame_00004.ply"));
  EXPECT_FALSE(fs::exists(out / "sheet.mp4"));  // the video of the scenario's name
  EXPECT_EQ(read_text(out / "notes.txt"), "mine");
  EXPECT_TRUE(fs::is_directory(out / "frames_i_kept"));
  EXPECT_EQ(stats_without_timings(out / "stats.csv").size(), 1u + 3u);  // header, frames 0 to 2
  const nlohmann::json resolved = nlohmann::json::parse(read_text(out / "scenario.json"));
  EXPECT_EQ(resolved["simulation"]["frames"], 2);  // the count run, not the file's
}

TEST(ResolvedScenario, FillsInEveryDefaultAndLoadsAgainAsItself) {
  const Scenario drape =
      load_scenario(TISSU_DATA_DIR "/scenarios/drape.json", {"simulation.pd.iterations=7"});
  const nlohmann::json resolved = nlohmann::json::parse(drape.resolved_json);
  EXPECT_EQ(resolved["name"], "drape");
  EXPECT_EQ(resolved["simulation"]["pd"]["iterations"], 7);  // the override
  EXPECT_EQ(resolved["simulation"]["frame_rate"], 30.0);     // a default
  EXPECT_EQ(resolved["simulation"]["newton"]["max_iterations"], drape.solver.newton.max_iterations);
  EXPECT_EQ(resolved["render"]["width"], 960);                             // given
  EXPECT_EQ(resolved["render"]["samples"], drape.render.options.samples);  // a default
  EXPECT_EQ(resolved["adaptive"]["enabled"], false);  // a section left out is off
  EXPECT_EQ(resolved["adaptive"]["min_edge_length"], drape.adaptive.refinement.min_edge_length_m);
  EXPECT_EQ(resolved["tearing"]["enabled"], false);
  EXPECT_EQ(resolved["obstacles"][1]["kinetic_friction"], 0.3);
  EXPECT_EQ(resolved["output"]["mesh_format"], "obj");

  const fs::path dir = test::fresh_dir_for_this_test("resolved_scenario");
  write_text(dir / "resolved.json", drape.resolved_json);
  EXPECT_EQ(load_scenario(dir / "resolved.json").resolved_json, drape.resolved_json);
}

TEST(ResolvedScenario, RunsFromAnotherFolderToTheSameResults) {
  const fs::path dir = test::fresh_dir_for_this_test("resolved_scenario");
  const Scenario original =
      load_scenario(write_sheet_scenario(dir), {"cloth.springs.structural.stiffness=300"});
  RunOptions options;
  options.output_dir = dir / "first";
  ASSERT_TRUE(run_scenario(original, options).ok);

  // the record of the first run, moved where the relative mesh path would not lead
  const fs::path elsewhere = dir / "elsewhere" / "deeper";
  fs::create_directories(elsewhere);
  fs::copy_file(dir / "first" / "scenario.json", elsewhere / "again.json");
  const Scenario again = load_scenario(elsewhere / "again.json");
  EXPECT_EQ(again.springs.structural.stiffness, 300.0);
  EXPECT_EQ(again.name, original.name);  // not the new file's stem
  options.output_dir = dir / "second";
  ASSERT_TRUE(run_scenario(again, options).ok);
  EXPECT_EQ(stats_without_timings(dir / "second" / "stats.csv"),
            stats_without_timings(dir / "first" / "stats.csv"));
  EXPECT_EQ(read_text(dir / "second" / "frame_00004.ply"),
            read_text(dir / "first" / "frame_00004.ply"));
}

}  // namespace
}  // namespace tissu
