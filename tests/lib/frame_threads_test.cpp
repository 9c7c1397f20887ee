// stats.csv's threads: the OpenMP threads each frame's steps ran on, so that a run whose program
// changes the count between frames (tissu run's FrameThreadChooser, lib/thread_count.hpp) says
// what each frame got.

#include <omp.h>

#include <gtest/gtest.h>

#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

TEST(FrameThreads, EachRowHasTheThreadsItsStepsRanOn) {
  const char* json = R"({
  "cloth": { "grid": { "size": [0.5, 0.5], "resolution": [6, 6] }, "density": 0.2,
             "springs": { "structural": { "stiffness": 500, "damping": 0.2 } } },
  "pins": [ { "side": "top" } ],
  "simulation": { "frames": 4, "substeps": 2, "integrator": "quasi_newton" },
  "output": { "meshes": false, "viewer": false, "point_cache": false },
  "render": { "enabled": false }
})";
  const int threads_before = omp_get_max_threads();
  // the next frame's threads, chosen after each frame as tissu run does: 3, 1, 2, 3 for frames
  // 1 to 4
  const std::vector<int> chosen_after_frame = {3, 1, 2, 3, 1};
  RunOptions options;
  options.output_dir = test::fresh_temp_dir("frame_threads");
  std::vector<int> recorded;
  options.on_frame = [&](const FrameStats& row) {
    recorded.push_back(row.threads);
    omp_set_num_threads(chosen_after_frame.at(row.frame));
  };
  const RunResult result = run_scenario(parse_scenario(json, "sheet.json"), options);
  omp_set_num_threads(threads_before);
  ASSERT_TRUE(result.ok) << result.failure;
  // frame 0, the start, has no steps
  EXPECT_EQ(recorded, (std::vector<int>{0, 3, 1, 2, 3}));
}

}  // namespace
}  // namespace tissu
