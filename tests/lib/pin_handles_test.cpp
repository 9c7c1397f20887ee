// Pins that move along keyframes, let go and take hold, run through the driver: the handles'
// particles land on their keys, a released cloth falls freely with the velocity it had, and a
// handle that takes hold stops what it holds. Mass is kept throughout.

#include "lib/pin_handles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/lib/scenario_errors.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

/// A 1 m x 0.5 m sheet in the x-z plane (rest = start positions), 0.25 m cells, 30 frames of one
/// step at 30 frames/s, with `pins` and `environment`.
std::string sheet(const std::string& pins, const std::string& environment = "{}", int frames = 30) {
  return R"({
  "cloth": { "grid": { "size": [1.0, 0.5], "resolution": [4, 2] }, "density": 0.2,
             "springs": { "structural": { "stiffness": 100, "damping": 0.1 },
                          "bending": { "stiffness": 0.01 } } },
  "pins": )" +
         pins + R"(,
  "environment": )" +
         environment + R"(,
  "simulation": { "frames": )" +
         std::to_string(frames) + R"(, "frame_rate": 30, "substeps": 1 },
  "output": { "meshes": false, "point_cache": false, "viewer": false }
})";
}

struct HandleRun {
  RunResult result;
  std::vector<FrameStats> frames;
  std::map<int, MaterialSurface> surfaces;  ///< by frame
  Scenario scenario;
};

HandleRun run(const std::string& json) {
  HandleRun out;
  out.scenario = parse_scenario(json, "handles.json");
  RunOptions options;
  options.output_dir =
      test::fresh_temp_dir(std::string("pin_handles/") +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
  options.on_frame = [&](const FrameStats& s) { out.frames.push_back(s); };
  options.on_surface = [&](int frame, const MaterialSurface& s) { out.surfaces[frame] = s; };
  out.result = run_scenario(out.scenario, options);
  return out;
}

bool on_top_side(const Eigen::Vector3d& rest) {
  return std::abs(rest.z() - 0.5) < 1e-9;
}

TEST(PinHandles, KeyframedHandlesCarryTheirParticlesThroughTheKeys) {
  // the top side slides 0.5 m along x while turning a quarter about y (about its middle), then
  // holds; linear and smooth keys land on the same poses at the keys
  for (const std::string interpolation : {"linear", "smooth"}) {
    const HandleRun r = run(sheet(R"([{ "side": "top", "motion": {
        "interpolation": ")" + interpolation +
                                  R"(", "pivot": [0.5, 0, 0.5],
        "keyframes": [ { "time": 0 },
                       { "time": 0.5, "offset": [0.5, 0, 0], "rotation": { "axis": [0, 1, 0], "degrees": 90 } } ] } }])"));
    ASSERT_TRUE(r.result.ok) << r.result.failure;
    const RigidMotion& motion = r.scenario.pins.at(0).motion;
    for (int frame : {5, 15, 30}) {
      const MaterialSurface& s = r.surfaces.at(frame);
      const double t = frame / 30.0;
      int checked = 0;
      for (std::size_t v = 0; v < s.rest_m.size(); ++v) {
        if (!on_top_side(s.rest_m[v])) continue;
        const Eigen::Vector3d expected = motion.pose(t).apply(s.rest_m[v]);  // started at rest
        EXPECT_LT((s.current.vertices[v] - expected).norm(), 1e-12)
            << interpolation << ", frame " << frame << ", vertex " << v;
        ++checked;
      }
      EXPECT_EQ(checked, 5);
    }
    // after the last key the side is upright along z, 0.5 m on, and holds
    const MaterialSurface& last = r.surfaces.at(30);
    for (std::size_t v = 0; v < last.rest_m.size(); ++v) {
      if (on_top_side(last.rest_m[v])) {
        EXPECT_NEAR(last.current.vertices[v].x(), 1.0, 1e-12);
      }
    }
  }
}

TEST(PinHandles, AReleasedClothFallsFreelyWithTheVelocityItHad) {
  // the whole sheet is carried at (0.3, 0, 1) m/s, then let go at 0.5 s: from then on each
  // particle falls freely, its velocity continuous at the release (backward Euler's discrete
  // fall: z gains h v_n with v_n = 1 - g h n)
  const HandleRun r = run(sheet(R"([{ "box": { "min": [-1, -1, -1], "max": [2, 1, 1] },
                                        "velocity": [0.3, 0, 1], "release_at": 0.5 }])",
                                R"({ "gravity": [0, 0, -9.81] })"));
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  EXPECT_EQ(r.frames.at(15).pinned, 15);  // frame 15 ends at t = 0.5 s: still held
  EXPECT_EQ(r.frames.at(16).pinned, 0);
  for (const FrameStats& row : r.frames) {
    EXPECT_NEAR(row.total_mass, r.frames.front().total_mass, 1e-15);
  }
  constexpr double h = 1.0 / 30.0, g = 9.81;
  double fall_m = 0.0;
  for (int n = 1; n <= 15; ++n) fall_m += h * (1.0 - g * h * n);
  const MaterialSurface& last = r.surfaces.at(30);
  for (std::size_t v = 0; v < last.rest_m.size(); ++v) {
    const Eigen::Vector3d expected =
        last.rest_m[v] + Eigen::Vector3d(0.3 * 1.0, 0.0, 1.0 * 0.5 + fall_m);
    EXPECT_LT((last.current.vertices[v] - expected).norm(), 1e-6) << "vertex " << v;
  }
}

TEST(PinHandles, AHandleThatTakesHoldStopsWhatItHolds) {
  // the sheet falls from rest; at 0.5 s a still handle takes hold of its top side
  const HandleRun r =
      run(sheet(R"([{ "side": "top", "attach_at": 0.5 }])", R"({ "gravity": [0, 0, -9.81] })", 45));
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  EXPECT_EQ(r.frames.at(15).pinned, 0);
  EXPECT_EQ(r.frames.at(16).pinned, 5);
  const MaterialSurface& held = r.surfaces.at(15);
  const MaterialSurface& later = r.surfaces.at(45);
  for (std::size_t v = 0; v < held.rest_m.size(); ++v) {
    if (!on_top_side(held.rest_m[v])) continue;
    EXPECT_LT(held.current.vertices[v].z(), -0.5);  // it fell before
    EXPECT_EQ(later.current.vertices[v], held.current.vertices[v]) << "vertex " << v;
  }
}

TEST(PinHandles, ParticlesRefinementAddsOnAHandleFollowIt) {
  // the top side moves and turns while adaptive refinement splits its edges: the particles added
  // on them are held too, and land where the handle carries their material points
  std::string json = sheet(R"([{ "side": "top", "motion": { "pivot": [0.5, 0, 0.5],
      "interpolation": "smooth", "keyframes": [ { "time": 0 },
      { "time": 0.5, "offset": [0.3, 0, 0.2], "rotation": { "axis": [0, 0, 1], "degrees": 60 } } ] } }])",
                           R"({ "gravity": [0, 0, -9.81] })");
  json.insert(json.rfind('}'),
              R"(, "adaptive": { "curvature": 0.1, "min_edge_length": 0.06, "every": 1 })");
  const HandleRun r = run(json);
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  int most_pinned = 0;
  for (const FrameStats& row : r.frames) {
    most_pinned = std::max(most_pinned, row.pinned);
    EXPECT_NEAR(row.total_mass, 0.1, 1e-15);  // 0.2 kg/m^2 x 0.5 m^2
  }
  EXPECT_GT(most_pinned, 5) << "no edge of the handle was split";
  const RigidMotion& motion = r.scenario.pins.at(0).motion;
  for (const auto& [frame, s] : r.surfaces) {
    for (std::size_t v = 0; v < s.rest_m.size(); ++v) {
      if (!on_top_side(s.rest_m[v])) continue;
      EXPECT_LT((s.current.vertices[v] - motion.pose(frame / 30.0).apply(s.rest_m[v])).norm(),
                1e-12)
          << "frame " << frame << ", vertex " << v;
    }
  }
}

TEST(PinHandles, ScheduleAndMotionMistakesAreNamed) {
  using test::scenario_error_of;
  const std::string base = sheet(R"([{ "side": "top" }])");
  EXPECT_EQ(scenario_error_of(base, {R"(pins.0.release_at=0)"}),
            "dir/s.json: pins[0].release_at: expected a time (s) after attach_at, got 0");
  EXPECT_EQ(scenario_error_of(base, {R"(pins.0.attach_at=1)", R"(pins.0.release_at=0.5)"}),
            "dir/s.json: pins[0].release_at: expected a time (s) after attach_at, got 0.5");
  EXPECT_EQ(scenario_error_of(base, {R"(pins.0.velocity=[0,0,1])", R"(pins.0.motion={})"}),
            "dir/s.json: pins[0].velocity: expected no \"velocity\" beside \"motion\" (give it as "
            "motion.velocity), got [0,0,1]");
  EXPECT_EQ(
      scenario_error_of(
          base, {R"(pins.0.motion={"keyframes": [{"time": 1, "rotation": {"degrees": 30}}]})"}),
      "dir/s.json: pins[0].motion.pivot: expected the point the keyframes' rotations turn "
      "about ([x, y, z], m)");
  EXPECT_EQ(scenario_error_of(base, {R"(pins.0.motion={"interpolation": "cubic"})"}),
            "dir/s.json: pins[0].motion.interpolation: expected one of \"linear\", \"smooth\", "
            "got \"cubic\"");
}

}  // namespace
}  // namespace tissu
