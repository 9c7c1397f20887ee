// Obstacles in rendered images: a tessellated sphere fills the pixels its silhouette covers, and a
// run draws its obstacles where they have moved to at each image's time, on a floor plane. Also a
// run's faces coloured by the sizing term that refined them.

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "lib/obstacle_mesh.hpp"
#include "lib/render/renderer.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

Eigen::Vector3f color_at(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return Eigen::Vector3f(p[0], p[1], p[2]) / 255.0f;
}

/// The RGB image in a PNG file; empty (0 x 0) if it cannot be read.
Image read_png(const std::filesystem::path& file) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(file.c_str(), &image.width, &image.height, &channels, 3);
  EXPECT_NE(data, nullptr) << file;
  if (!data) return Image{};
  image.rgb.assign(data, data + 3 * image.width * image.height);
  stbi_image_free(data);
  return image;
}

/// Whether `c` is `base` lit, that is darkened or brightened by a factor in [0.25, 1.1], give or
/// take a little specular white: how the renderer shades a surface of colour `base`.
bool is_shade_of(const Eigen::Vector3f& c, const Eigen::Vector3f& base) {
  const float scale = c.dot(base) / base.squaredNorm();
  return scale >= 0.25f && scale <= 1.1f && (c - scale * base).norm() < 0.04f;
}

/// The ray from the camera through the centre of pixel (x, y) (row 0 at the top), unit.
Eigen::Vector3d pixel_ray(const Camera& camera, int width, int height, int x, int y) {
  const Eigen::Vector3d forward = (camera.target - camera.position).normalized();
  const Eigen::Vector3d right = forward.cross(camera.up).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const double half_y = std::tan(camera.fov_y_deg / 2.0 * std::numbers::pi / 180.0);
  const double half_x = half_y * width / height;
  const double ndc_x = 2.0 * (x + 0.5) / width - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / height;
  return (forward + ndc_x * half_x * right + ndc_y * half_y * up).normalized();
}

/// Pixel (column, row from the top) where world point p appears.
Eigen::Vector2i pixel_of(const Camera& camera, int width, int height, const Eigen::Vector3d& p) {
  const Eigen::Matrix4d vp =
      (projection_matrix(camera, double(width) / height, 0.1, 100.0) * view_matrix(camera))
          .cast<double>();
  const Eigen::Vector4d clip = vp * p.homogeneous();
  return {int((clip.x() / clip.w() + 1.0) / 2.0 * width),
          int((1.0 - clip.y() / clip.w()) / 2.0 * height)};
}

TEST(ObstacleRender, ASphereFillsItsSilhouetteInTheObstacleColour) {
  RenderOptions options;
  options.width = 160;
  options.height = 120;
  Renderer renderer(options);
  Obstacle ball;
  ball.shape = ObstacleShape::sphere;
  ball.position = {0.4, 0.3, 0.2};  // off the image centre: the silhouette is not a circle
  ball.radius_m = 0.5;
  const std::vector<IndexedMesh> obstacles{obstacle_mesh(ball, 0.0)};
  const IndexedMesh no_cloth;
  RenderScene scene;
  scene.mesh = &no_cloth;
  scene.obstacles = obstacles;
  Camera camera;
  camera.position = {0.0, -3.0, 0.6};
  camera.target = Eigen::Vector3d::Zero();
  const Image image = renderer.render(scene, camera);

  int inside = 0, outside = 0;
  for (int y = 0; y < options.height; ++y) {
    for (int x = 0; x < options.width; ++x) {
      // how far the pixel's ray passes from the centre, in radii
      const Eigen::Vector3d ray = pixel_ray(camera, options.width, options.height, x, y);
      const Eigen::Vector3d to_centre = ball.position - camera.position;
      const double miss = (to_centre - to_centre.dot(ray) * ray).norm() / ball.radius_m;
      const Eigen::Vector3f c = color_at(image, x, y);
      if (miss < 0.97) {
        ++inside;
        EXPECT_TRUE(is_shade_of(c, options.obstacle_color))
            << "pixel " << x << "," << y << " in the silhouette: " << c.transpose();
      } else if (miss > 1.03) {
        ++outside;
        EXPECT_LT((c - options.background_color).norm(), 1.5f / 255)
            << "pixel " << x << "," << y << " outside the silhouette: " << c.transpose();
      }
    }
  }
  EXPECT_GT(inside, 1500);  // a disc some 25 pixels across
  EXPECT_GT(outside, 10000);
}

TEST(ObstacleRender, ARunDrawsItsObstaclesWhereTheyHaveMovedAndAFloorAsTheGround) {
  // a hanging cloth over x, z in [0, 1]; a ball beside it rising at 6 m/s; a floor under both
  const Scenario scenario = parse_scenario(R"({
    "cloth": { "grid": { "size": [1, 1], "resolution": [4, 4] }, "density": 0.2,
               "springs": { "structural": { "stiffness": 200, "damping": 0.1 } } },
    "pins": [ { "side": "top" } ],
    "obstacles": [
      { "type": "plane", "point": [0, 0, -0.5], "normal": [0, 0, 1] },
      { "type": "sphere", "center": [1.8, 0, 0.5], "radius": 0.3, "motion": { "velocity": [0, 0, 6] } }
    ],
    "simulation": { "frames": 2, "frame_rate": 30, "substeps": 2 },
    "render": { "width": 160, "height": 120, "every": 2, "video": false,
                "camera": { "position": [0.9, -5, 1.2], "target": [0.9, 0, 0.5] } }
  })",
                                           "obstacle_render.json");
  RunOptions run;
  run.output_dir = test::fresh_temp_dir("obstacle_render");
  const RunResult result = run_scenario(scenario, run);
  ASSERT_TRUE(result.ok) << result.failure;
  ASSERT_EQ(result.images, 2);  // frames 0 and 2: t = 0 and 1/15 s, the ball 0.4 m higher

  const auto read = [&](const char* name) { return read_png(run.output_dir / name); };
  const Image first = read("frame_00000.png"), last = read("frame_00002.png");  // by frame
  ASSERT_EQ(first.width, 160);
  ASSERT_EQ(last.width, 160);
  const RenderOptions defaults;
  const Camera& camera = *scenario.render.camera;
  const auto at = [&](const Image& image, const Eigen::Vector3d& p) {
    const Eigen::Vector2i px = pixel_of(camera, 160, 120, p);
    return color_at(image, px.x(), px.y());
  };
  const Eigen::Vector3d start(1.8, 0.0, 0.5), low(1.8, 0.0, 0.35), moved(1.8, 0.0, 0.9);
  EXPECT_TRUE(is_shade_of(at(first, start), defaults.obstacle_color)) << at(first, start);
  EXPECT_TRUE(is_shade_of(at(first, low), defaults.obstacle_color)) << at(first, low);
  EXPECT_TRUE(is_shade_of(at(last, moved), defaults.obstacle_color)) << at(last, moved);
  EXPECT_FALSE(is_shade_of(at(last, low), defaults.obstacle_color)) << at(last, low);
  // the floor plane is the ground, at the bottom of both images
  for (const Image* image : {&first, &last}) {
    const Eigen::Vector3f floor = color_at(*image, 80, 117);
    EXPECT_LT((floor - defaults.ground_color).norm(), 0.15f) << floor.transpose();
    EXPECT_GT((floor - defaults.background_color).norm(), 0.1f) << floor.transpose();
  }
}

TEST(SizingRender, AnAdaptiveRunColoursItsFacesByTheTermThatRefinedThem) {
  // 25 cm cells, refined until no edge is longer than 20 cm: after the first adaptation pass the
  // maximum edge length holds every face
  const Scenario scenario = parse_scenario(R"({
    "cloth": { "grid": { "size": [1, 1], "resolution": [4, 4] }, "density": 0.2,
               "springs": { "structural": { "stiffness": 200, "damping": 0.1 } } },
    "pins": [ { "side": "top" } ],
    "adaptive": { "max_edge_length": 0.2, "min_edge_length": 0.05 },
    "simulation": { "frames": 2, "frame_rate": 30, "substeps": 2 },
    "render": { "width": 160, "height": 120, "every": 2, "video": false, "color_mode": "sizing",
                "camera": { "position": [0.5, -3, 0.5], "target": [0.5, 0, 0.5] } }
  })",
                                           "sizing_render.json");
  RunOptions run;
  run.output_dir = test::fresh_temp_dir("sizing_render");
  const RunResult result = run_scenario(scenario, run);
  ASSERT_TRUE(result.ok) << result.failure;
  ASSERT_EQ(result.images, 2);
  const auto centre_of = [&](const char* name) {
    const Image image = read_png(run.output_dir / name);
    const Eigen::Vector2i px = pixel_of(*scenario.render.camera, 160, 120, {0.5, 0.0, 0.45});
    return image.width == 160 ? color_at(image, px.x(), px.y()) : Eigen::Vector3f::Zero().eval();
  };
  // lib/render/shader_sources.hpp's term_color(): none light grey, max_edge_length reddish purple
  const Eigen::Vector3f none(0.85f, 0.85f, 0.85f), max_edge_length(0.80f, 0.47f, 0.65f);
  const Eigen::Vector3f before = centre_of("frame_00000.png");  // before any pass
  const Eigen::Vector3f after = centre_of("frame_00002.png");
  EXPECT_TRUE(is_shade_of(before, none)) << before.transpose();
  EXPECT_TRUE(is_shade_of(after, max_edge_length)) << after.transpose();
}

}  // namespace
}  // namespace tissu
