// Faults during a run: a stop request (what SIGINT and SIGTERM become) ends it after its last
// whole frame, with as many stats.csv rows as meshes; a write the disk refuses ends it with an
// error naming the file and leaves no half-written file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <string>
#include <vector>

#include "lib/atomic_file.hpp"
#include "lib/mesh_io/read_mesh.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/file_size_limit.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

/// A small sheet hanging from two corners for `frames` frames, rendered when `render`.
Scenario sheet(int frames, int resolution, bool render) {
  return parse_scenario(R"({
    "cloth": { "grid": { "size": [1, 1], "resolution": [)" +
                            std::to_string(resolution) + ", " + std::to_string(resolution) +
                            R"(] }, "density": 0.2,
               "springs": { "structural": { "stiffness": 100 } } },
    "pins": [ { "corners": ["top_left", "top_right"] } ],
    "simulation": { "frames": )" +
                            std::to_string(frames) +
                            R"(, "substeps": 5 },
    "render": { "enabled": )" +
                            (render ? "true" : "false") +
                            R"(, "width": 64, "height": 48, "video": false } })",
                        "sheet.json");
}

/// The rows of `dir`/stats.csv after its header.
int stats_rows(const fs::path& dir) {
  std::ifstream in(dir / "stats.csv");
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines - 1;
}

/// The files of `dir` named `prefix`*`suffix` (prefix ".": the hidden ones, temporaries).
int count_files(const fs::path& dir, const std::string& prefix, const std::string& suffix) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && name.size() >= suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      ++n;
  }
  return n;
}

TEST(RunFaults, AStopRequestEndsTheRunAfterItsLastWholeFrameWithARowPerMesh) {
  const fs::path dir = test::fresh_dir_for_this_test("run_faults");
  volatile std::sig_atomic_t flag = 0;
  RunOptions options;
  options.output_dir = dir;
  options.stop.flag = &flag;
  options.on_frame = [&](const FrameStats& row) {
    if (row.frame == 2) flag = SIGTERM;  // as the handler would, in the middle of the run
  };
  const RunResult result = run_scenario(sheet(30, 4, true), options);
  EXPECT_TRUE(result.ok);
  EXPECT_TRUE(result.stopped);
  EXPECT_EQ(result.frames_done, 2);
  EXPECT_EQ(result.images, 0);  // nothing is rendered after a stop
  EXPECT_EQ(stats_rows(dir), 3);
  EXPECT_EQ(count_files(dir, "frame_", ".obj"), 3);
  EXPECT_EQ(count_files(dir, "frame_", ".png"), 0);
  EXPECT_EQ(count_files(dir, ".", ""), 0);  // no temporary left
  for (int f = 0; f <= 2; ++f) {
    EXPECT_EQ(read_mesh(dir / ("frame_0000" + std::to_string(f) + ".obj")).vertices.size(), 25u);
  }
}

TEST(RunFaults, AStopRequestWhileRenderingKeepsTheWholeImagesOnly) {
  const fs::path dir = test::fresh_dir_for_this_test("run_faults");
  volatile std::sig_atomic_t flag = 0;
  RunOptions options;
  options.output_dir = dir;
  options.stop.flag = &flag;
  options.on_image = [&](int done, int) {
    if (done == 2) flag = SIGINT;
  };
  const RunResult result = run_scenario(sheet(5, 4, true), options);
  EXPECT_TRUE(result.stopped);
  EXPECT_EQ(result.frames_done, 5);
  EXPECT_EQ(result.images, 2);
  EXPECT_EQ(count_files(dir, "frame_", ".png"), 2);
  EXPECT_EQ(stats_rows(dir), 6);
}

TEST(RunFaults, AMeshTheDiskRefusesEndsTheRunNamingItAndLeavesNoPartOfIt) {
  // a 40 x 40 grid's OBJ is about 200 kB: under a 64 KiB file size limit stats.csv fits, the
  // first frame's mesh does not
  const fs::path dir = test::fresh_dir_for_this_test("run_faults");
  RunOptions options;
  options.output_dir = dir;
  Scenario scenario = sheet(3, 40, false);
  scenario.output.viewer = false;  // its 570 kB page would be refused first
  try {
    const test::FileSizeLimit limit(64 * 1024);
    run_scenario(scenario, options);
    FAIL() << "the run wrote a 200 kB mesh under a 64 KiB limit";
  } catch (const FileWriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr((dir / "frame_00000.obj").string() + ": cannot write mesh: "));
  }
  EXPECT_EQ(count_files(dir, "frame_", ""), 0);
  EXPECT_EQ(count_files(dir, ".", ""), 0);
  EXPECT_EQ(stats_rows(dir), 0);  // frame 0 is not recorded without its mesh
}

}  // namespace
}  // namespace tissu
