// Rendering as scenarios and the render command use it: sizes, counts, and rejected settings.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "lib/render_folder.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"
#include "tests/video_probe.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

const char* const small_cloth = R"({
  "cloth": { "grid": { "size": [1, 1], "resolution": [6, 6] }, "density": 0.2,
             "springs": { "structural": { "stiffness": 200, "damping": 0.1 } } },
  "pins": [ { "side": "top" } ],
  "simulation": { "frames": 4, "substeps": 4 }
})";

std::string render_error(const std::string& render_json) {
  try {
    parse_scenario(small_cloth, "r.json", {"render=" + render_json});
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "no error";
}

/// Width and height from a PNG's IHDR chunk (big-endian, bytes 16 to 23).
std::pair<int, int> png_size(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  auto be32 = [&](int at) {
    return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3];
  };
  return {be32(16), be32(20)};
}

std::filesystem::path fresh_dir(const std::string& name) {
  return test::fresh_temp_dir(name);
}

int count_png(const std::filesystem::path& dir) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    count += entry.path().extension() == ".png";
  }
  return count;
}

TEST(RenderRun, ScenarioWithRenderingWritesOnePngPerRenderedFrameOfTheConfiguredSize) {
  const Scenario scenario = parse_scenario(
      small_cloth, "r.json",
      {R"(render={"width": 96, "height": 64, "every": 2, "video": false, "wireframe": true})"});
  RunOptions options;
  options.output_dir = fresh_dir("render_run");
  int reported = 0;
  options.on_image = [&](int done, int total) {
    reported = done;
    EXPECT_EQ(total, 3);
  };
  const RunResult result = run_scenario(scenario, options);
  ASSERT_TRUE(result.ok) << result.failure;
  EXPECT_EQ(result.images, 3);  // frames 0, 2 and 4
  EXPECT_EQ(reported, 3);
  EXPECT_EQ(count_png(options.output_dir), 3);
  for (const int frame : {0, 2, 4}) {  // named by the frame they show, not by image
    const auto file = options.output_dir / ("frame_0000" + std::to_string(frame) + ".png");
    EXPECT_EQ(png_size(file), std::make_pair(96, 64)) << file;
  }
  EXPECT_FALSE(std::filesystem::exists(options.output_dir / "r.mp4"));
}

bool ffmpeg_installed() {
  return std::system("command -v ffmpeg > /dev/null 2>&1 && command -v ffprobe > /dev/null 2>&1") ==
         0;
}

TEST(RenderRun, EveryNthFrameStillMakesAVideoOfAllItsImages) {
  if (!ffmpeg_installed()) GTEST_SKIP() << "ffmpeg or ffprobe is not installed";
  const Scenario scenario = parse_scenario(small_cloth, "gaps.json",
                                           {R"(render={"width": 32, "height": 32, "every": 2})"});
  RunOptions options;
  options.output_dir = fresh_dir("render_every_video");
  const RunResult result = run_scenario(scenario, options);
  ASSERT_TRUE(result.ok) << result.failure;
  EXPECT_EQ(result.video_warning, "");
  EXPECT_TRUE(std::filesystem::exists(options.output_dir / "frame_00004.png"));
  EXPECT_EQ(test::video_frame_count(options.output_dir / "gaps.mp4"), 3);  // frames 0, 2 and 4
}

TEST(RenderRun, RenderingIsOffByDefault) {
  RunOptions options;
  options.output_dir = fresh_dir("render_off");
  ASSERT_TRUE(run_scenario(parse_scenario(small_cloth, "r.json"), options).ok);
  EXPECT_EQ(count_png(options.output_dir), 0);
}

TEST(RenderRun, SavedFramesRenderAgainWithoutSimulating) {
  RunOptions options;
  options.output_dir = fresh_dir("render_again");
  ASSERT_TRUE(run_scenario(parse_scenario(small_cloth, "r.json"), options).ok);
  RenderSettings settings;
  settings.options.width = 64;
  settings.options.height = 32;
  settings.video = false;
  const auto images = fresh_dir("render_again_images");
  const RenderedRun run = render_mesh_folder(options.output_dir, settings, 30.0, images);
  EXPECT_EQ(run.images, 5);
  EXPECT_EQ(count_png(images), 5);
  EXPECT_EQ(png_size(images / "frame_00004.png"), std::make_pair(64, 32));
  EXPECT_THROW(render_mesh_folder(images, settings, 30.0, images), std::runtime_error);
}

TEST(RenderRun, SavedFramesRenderedAgainAreNamedAfterTheirMeshes) {
  // meshes of every 3rd frame (and the last): frame_00000, 3, 6, 9, 10
  RunOptions options;
  options.output_dir = fresh_dir("render_again_gaps");
  options.frames = 10;
  ASSERT_TRUE(
      run_scenario(parse_scenario(small_cloth, "r.json", {"output.mesh_every=3"}), options).ok);
  RenderSettings settings;
  settings.options.width = 32;
  settings.options.height = 32;
  settings.video = false;
  const auto images = fresh_dir("render_again_gaps_images");
  EXPECT_EQ(render_mesh_folder(options.output_dir, settings, 10.0, images).images, 5);
  for (const char* name : {"frame_00000.png", "frame_00003.png", "frame_00006.png",
                           "frame_00009.png", "frame_00010.png"}) {
    EXPECT_TRUE(std::filesystem::exists(images / name)) << name;
  }
  EXPECT_EQ(count_png(images), 5);
}

TEST(RenderRun, BrokenCamerasAndOddSizesAreRejectedWithTheKeyPath) {
  EXPECT_EQ(render_error(R"({"width": 641})"),
            "r.json: render.width: expected an even number of pixels (video encoders need it), "
            "got 641");
  EXPECT_THAT(render_error(R"({"height": 1})"),
              HasSubstr("render.height: expected an integer from 2"));
  EXPECT_THAT(
      render_error(R"({"camera": {"position": [0, -3, 1], "target": [0, 0, 0], "fov": 0}})"),
      HasSubstr(
          "r.json: render.camera.fov: expected a vertical field of view in (0, 179] degrees"));
  EXPECT_THAT(render_error(R"({"camera": {"position": [1, 2, 3], "target": [1, 2, 3]}})"),
              HasSubstr("r.json: render.camera: camera: target"));
  EXPECT_THAT(render_error(R"({"colour_mode": "strain"})"),
              HasSubstr("render.colour_mode: unknown key; did you mean 'color_mode'?"));
}

}  // namespace
}  // namespace tissu
