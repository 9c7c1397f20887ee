// stats.csv's strain_limited: how many structural springs the strain limit shortened in each
// frame, so that a run shows how much of the cloth the limit holds rather than its springs.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

/// A soft 0.5 m sheet of 8 x 8 cells hanging from its two top corners, 12 frames; the stepped
/// frames' rows.
std::vector<FrameStats> soft_sheet_rows(double strain_limit) {
  const std::string json = R"({
  "cloth": { "grid": { "size": [0.5, 0.5], "resolution": [8, 8] }, "density": 0.2,
             "springs": { "structural": { "stiffness": 5 }, "bending": { "stiffness": 0.001 } } },
  "pins": [ { "corners": ["top_left", "top_right"] } ],
  "simulation": { "frames": 12, "substeps": 4, "strain_limit": )" +
                           std::to_string(strain_limit) + R"( },
  "output": { "meshes": false, "viewer": false, "point_cache": false },
  "render": { "enabled": false }
})";
  RunOptions options;
  options.output_dir = test::fresh_temp_dir("strain_limit_stats");
  std::vector<FrameStats> rows;
  options.on_frame = [&](const FrameStats& row) {
    if (row.frame > 0) rows.push_back(row);
  };
  const RunResult result = run_scenario(parse_scenario(json, "sheet.json"), options);
  EXPECT_TRUE(result.ok) << result.failure;
  return rows;
}

TEST(StrainLimitStats, CountsTheSpringsTheLimitShortens) {
  // without a limit the soft sheet stretches well past 5 %, and nothing is counted
  double largest_free_stretch = 0.0;
  for (const FrameStats& row : soft_sheet_rows(0.0)) {
    EXPECT_EQ(row.strain_limited, 0) << "frame " << row.frame;
    largest_free_stretch = std::max(largest_free_stretch, row.max_stretch);
  }
  EXPECT_GT(largest_free_stretch, 0.2);
  // with a 5 % limit, once the sheet has sagged, every frame shortens some of its springs, and
  // never more than all of them in each of the frame's 4 steps
  const std::vector<FrameStats> limited = soft_sheet_rows(0.05);
  ASSERT_EQ(limited.size(), 12u);
  for (std::size_t k = 6; k < limited.size(); ++k) {
    EXPECT_GT(limited[k].strain_limited, 0) << "frame " << limited[k].frame;
    EXPECT_LE(limited[k].strain_limited, 4 * limited[k].springs) << "frame " << limited[k].frame;
    EXPECT_LT(limited[k].max_stretch, 0.1) << "frame " << limited[k].frame;
  }
}

}  // namespace
}  // namespace tissu
