#include "lib/render/renderer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "render_test_support.hpp"
#include "topology/refinement_options.hpp"

namespace tissu {
namespace {

using test::color_at;
using test::color_distance;

constexpr int width = 160;
constexpr int height = 120;
constexpr double distance_m = 2.5;  // from the camera to the square's centre
constexpr double fov_deg = 40.0;

RenderOptions small_options() {
  RenderOptions options;
  options.width = width;
  options.height = height;
  return options;
}

/// Looks at the origin along -z from (0, 0, distance_m) (or along +z from behind), image up = +y.
Camera square_camera(bool from_behind = false) {
  Camera camera;
  camera.position = {0.0, 0.0, from_behind ? -distance_m : distance_m};
  camera.target = Eigen::Vector3d::Zero();
  camera.up = {0.0, 1.0, 0.0};
  camera.fov_y_deg = fov_deg;
  return camera;
}

/// Pixel (column, row from the top) where world point p appears.
Eigen::Vector2d pixel_of(const Camera& camera, const Eigen::Vector3d& p) {
  const Eigen::Matrix4d vp =
      (projection_matrix(camera, double(width) / height, 0.1, 10.0) * view_matrix(camera))
          .cast<double>();
  const Eigen::Vector4d clip = vp * p.homogeneous();
  return {(clip.x() / clip.w() + 1.0) / 2.0 * width, (1.0 - clip.y() / clip.w()) / 2.0 * height};
}

/// Pixels of `image` farther than `threshold` from `background`.
int pixels_unlike(const Image& image, const Eigen::Vector3f& background, float threshold) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      count += color_distance(color_at(image, x, y), background) > threshold;
  return count;
}

class FlatSquare : public ::testing::TestWithParam<int> {};

TEST_P(FlatSquare, FillsTheAreaTheProjectionPredictsWithTheLitFrontColour) {
  RenderOptions options = small_options();
  options.samples = GetParam();
  Renderer renderer(options);
  const IndexedMesh mesh = test::square_mesh(1.0, 4);
  const Image image = renderer.render(test::scene_of(mesh), square_camera());
  ASSERT_EQ(image.width, width);
  ASSERT_EQ(image.height, height);
  ASSERT_EQ(image.rgb.size(), 3u * width * height);

  for (const auto& [x, y] :
       {std::pair{0, 0}, {width - 1, 0}, {0, height - 1}, {width - 1, height - 1}})
    EXPECT_LT(color_distance(color_at(image, x, y), options.background_color), 1.5f / 255)
        << "corner " << x << "," << y;

  const Eigen::Vector3f centre = color_at(image, width / 2, height / 2);
  EXPECT_LT(color_distance(centre, options.front_color),
            color_distance(centre, options.back_color));
  EXPECT_LT(color_distance(centre, options.front_color), 0.3f) << centre.transpose();
  EXPECT_GT(centre.x(), 2.0f * centre.z());                // red, as the front colour
  EXPECT_LT(centre.x(), options.front_color.x() + 0.02f);  // shaded, not brighter than the colour

  // the square's half extents in normalised device coordinates
  const double t = std::tan(fov_deg / 2.0 * std::numbers::pi / 180.0);
  const double half_y = 0.5 / (distance_m * t), half_x = half_y * height / width;
  const double expected = half_x * half_y * width * height;
  const float half_contrast = 0.5f * color_distance(options.background_color, centre);
  const int covered = pixels_unlike(image, options.background_color, half_contrast);
  EXPECT_NEAR(covered, expected, 0.03 * expected);
}

INSTANTIATE_TEST_SUITE_P(Samples, FlatSquare, ::testing::Values(1, 4));

TEST(Renderer, ShowsTheBackColourFromBehind) {
  const RenderOptions options = small_options();
  Renderer renderer(options);
  const IndexedMesh mesh = test::square_mesh(1.0, 4);
  const Image image = renderer.render(test::scene_of(mesh), square_camera(true));
  const Eigen::Vector3f centre = color_at(image, width / 2, height / 2);
  EXPECT_LT(color_distance(centre, options.back_color), color_distance(centre, options.front_color))
      << centre.transpose();
  EXPECT_GT(centre.z(), centre.x());  // blue-grey, not red
}

TEST(Renderer, PutsWhatIsAboveTheViewCentreInTheTopRows) {
  Renderer renderer(small_options());
  const IndexedMesh mesh = test::square_mesh(0.4, 2, true, {0.0, 0.5, 0.0});
  const Image image = renderer.render(test::scene_of(mesh), square_camera());
  const Eigen::Vector3f background = renderer.options().background_color;
  int top = 0, bottom = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      (y < height / 2 ? top : bottom) += color_distance(color_at(image, x, y), background) > 0.1f;
  EXPECT_GT(top, 100);
  EXPECT_EQ(bottom, 0);
}

TEST(Renderer, WireframeDrawsPolygonEdgesButNotTheQuadDiagonals) {
  RenderOptions options = small_options();
  Renderer plain(options);
  options.wireframe = true;
  options.wireframe_opacity = 1.0f;  // full contrast: lines are told apart from the cloth
  Renderer wired(options);
  const Camera camera = square_camera();

  // 2 x 2 quads: the inner edges x = 0 and y = 0 cross the image centre
  const IndexedMesh quads = test::square_mesh(1.0, 2, true);
  const Image a = plain.render(test::scene_of(quads), camera);
  const Image b = wired.render(test::scene_of(quads), camera);
  const Eigen::Vector2d on_edge = pixel_of(camera, {0.0, 0.25, 0.0});  // on the edge x = 0
  // a one-pixel line on a pixel border darkens the two pixels beside it by half each
  float darkening = 0.0f;
  for (int dx = -2; dx <= 2; ++dx) {
    const int x = int(on_edge.x()) + dx, y = int(on_edge.y());
    darkening += color_distance(color_at(a, x, y), color_at(b, x, y));
  }
  EXPECT_GT(darkening, 0.4f) << "no edge line at x = 0";
  // a quad's centre is on its fan diagonal: left alone when quads are drawn as quads
  const Eigen::Vector2d quad_centre = pixel_of(camera, {0.25, 0.25, 0.0});
  const int x = int(std::round(quad_centre.x())), y = int(std::round(quad_centre.y()));
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx)
      EXPECT_LT(color_distance(color_at(a, x + dx, y + dy), color_at(b, x + dx, y + dy)), 0.02f);

  // the same square in triangles: the diagonal is an edge and shows
  const IndexedMesh triangles = test::square_mesh(1.0, 2, false);
  const Image c = plain.render(test::scene_of(triangles), camera);
  const Image d = wired.render(test::scene_of(triangles), camera);
  float diagonal = 0.0f;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx)
      diagonal = std::max(diagonal,
                          color_distance(color_at(c, x + dx, y + dy), color_at(d, x + dx, y + dy)));
  EXPECT_GT(diagonal, 0.3f);
}

TEST(Renderer, StrainModeColoursRestWhiteStretchRedAndCompressionBlue) {
  RenderOptions options = small_options();
  options.color_mode = ColorMode::strain;
  Renderer renderer(options);
  const IndexedMesh mesh = test::square_mesh(1.0, 2);
  RenderScene scene = test::scene_of(mesh);
  const auto centre_with_strain = [&](float strain) {
    scene.face_strain.assign(mesh.faces.size(), strain);
    return color_at(renderer.render(scene, square_camera()), width / 2 + 10, height / 2 + 10);
  };
  const Eigen::Vector3f rest = centre_with_strain(0.0f);
  const Eigen::Vector3f stretched = centre_with_strain(0.5f);
  const Eigen::Vector3f compressed = centre_with_strain(-0.5f);
  EXPECT_LT(rest.maxCoeff() - rest.minCoeff(), 0.03f) << rest.transpose();  // grey-white
  EXPECT_GT(stretched.x(), 3.0f * stretched.z()) << stretched.transpose();
  EXPECT_GT(compressed.z(), 2.0f * compressed.x()) << compressed.transpose();
}

TEST(Renderer, LevelModeColoursFinerFacesDarker) {
  RenderOptions options = small_options();
  options.color_mode = ColorMode::level;
  Renderer renderer(options);
  const IndexedMesh mesh = test::square_mesh(1.0, 2);
  RenderScene scene = test::scene_of(mesh);
  scene.face_strain.assign(mesh.faces.size(), 0.5f);  // ignored in this mode
  const auto centre_at_level = [&](float level) {
    scene.face_level.assign(mesh.faces.size(), level);
    return color_at(renderer.render(scene, square_camera()), width / 2 + 10, height / 2 + 10);
  };
  const Eigen::Vector3f input = centre_at_level(0.0f);
  const Eigen::Vector3f once = centre_at_level(1.0f);
  const Eigen::Vector3f finer = centre_at_level(3.2f);  // rounds to 3
  EXPECT_GT(input.sum(), once.sum() + 0.2f) << input.transpose() << " / " << once.transpose();
  EXPECT_GT(once.sum(), finer.sum() + 0.2f) << once.transpose() << " / " << finer.transpose();
  EXPECT_GT(input.x(), input.z()) << input.transpose();  // warm, not the strain map's white
}

TEST(Renderer, SizingModeGivesEachTermItsOwnColour) {
  RenderOptions options = small_options();
  options.color_mode = ColorMode::sizing_term;
  Renderer renderer(options);
  const IndexedMesh mesh = test::square_mesh(1.0, 2);
  RenderScene scene = test::scene_of(mesh);
  scene.face_level.assign(mesh.faces.size(), 3.0f);  // ignored in this mode
  const auto centre_with_term = [&](SizingTerm term) {
    scene.face_sizing_term.assign(mesh.faces.size(), static_cast<float>(term));
    return color_at(renderer.render(scene, square_camera()), width / 2 + 10, height / 2 + 10);
  };
  const SizingTerm terms[] = {SizingTerm::none,      SizingTerm::curvature,
                              SizingTerm::velocity,  SizingTerm::strain,
                              SizingTerm::obstacles, SizingTerm::max_edge_length};
  std::vector<Eigen::Vector3f> colours;
  for (const SizingTerm term : terms) colours.push_back(centre_with_term(term));
  const Eigen::Vector3f none = colours[0];
  EXPECT_LT(none.maxCoeff() - none.minCoeff(), 0.03f) << none.transpose();     // grey
  EXPECT_GT(colours[1].z(), 2.0f * colours[1].x()) << colours[1].transpose();  // curvature blue
  EXPECT_GT(colours[3].x(), 2.0f * colours[3].z()) << colours[3].transpose();  // strain warm
  for (std::size_t a = 0; a < colours.size(); ++a) {
    for (std::size_t b = a + 1; b < colours.size(); ++b) {
      EXPECT_GT((colours[a] - colours[b]).cwiseAbs().maxCoeff(), 0.1f)
          << "terms " << a << " and " << b << ": " << colours[a].transpose() << " / "
          << colours[b].transpose();
    }
  }
}

TEST(Renderer, MarksPinnedParticles) {
  RenderOptions options = small_options();
  const IndexedMesh mesh = test::square_mesh(1.0, 2);
  RenderScene scene = test::scene_of(mesh);
  scene.pinned.assign(mesh.vertices.size(), 0);
  scene.pinned[4] = 1;  // the centre vertex
  const Camera camera = square_camera();
  const Eigen::Vector2d at = pixel_of(camera, {0.0, 0.0, 0.0});
  const int x = int(at.x()) + 1, y = int(at.y()) + 1;
  const Eigen::Vector3f marked = color_at(Renderer(options).render(scene, camera), x, y);
  options.show_pins = false;
  const Eigen::Vector3f unmarked = color_at(Renderer(options).render(scene, camera), x, y);
  EXPECT_LT(color_distance(marked, options.pin_color), 0.05f) << marked.transpose();
  EXPECT_GT(color_distance(unmarked, options.pin_color), 0.3f);
}

TEST(Renderer, DrawsTheGroundUnderTheCloth) {
  const RenderOptions options = small_options();
  Renderer renderer(options);
  const IndexedMesh mesh = test::square_mesh(1.0, 2);
  Camera camera;
  camera.position = {0.0, -2.5, 1.2};
  camera.target = Eigen::Vector3d::Zero();
  RenderScene scene = test::scene_of(mesh);
  scene.ground_height_m = -0.5;
  const Image with_ground = renderer.render(scene, camera);
  const Eigen::Vector3f floor = color_at(with_ground, width / 2, height - 3);
  EXPECT_LT(color_distance(floor, options.ground_color), 0.15f) << floor.transpose();
  EXPECT_LT(color_distance(color_at(with_ground, width / 2, 2), options.background_color), 0.02f);
  scene.ground_height_m.reset();
  const Image without = renderer.render(scene, camera);
  EXPECT_LT(color_distance(color_at(without, width / 2, height - 3), options.background_color),
            0.02f);
}

TEST(Renderer, DrawsObstaclesFlatInTheirColourWithoutWireframeAndBehindTheCloth) {
  RenderOptions options = small_options();
  options.obstacle_color = {0.20f, 0.75f, 0.30f};  // green: unlike every other colour drawn
  options.wireframe = true;
  options.wireframe_opacity = 1.0f;
  Renderer wired(options);
  options.wireframe = false;
  Renderer plain(options);
  const Camera camera = square_camera();  // looking down -z
  // the cloth at z = 0 over x in [-0.4, 0.2]; the cube's top at z = -0.05 under x in [0, 0.5]:
  // the cube lies beyond the cloth's depth range, so it shows only if it is clipped as itself
  const IndexedMesh cloth = test::square_mesh(0.6, 3, true, {-0.1, 0.0, 0.0});
  const std::vector<IndexedMesh> obstacles{test::cube_mesh({0.25, 0.0, -0.3}, 0.25)};
  RenderScene scene = test::scene_of(cloth);
  scene.obstacles = obstacles;
  const Image image = wired.render(scene, camera);
  const Image unwired = plain.render(scene, camera);

  const auto at = [&](const Image& im, const Eigen::Vector3d& p) {
    const Eigen::Vector2d px = pixel_of(camera, p);
    return color_at(im, int(px.x()), int(px.y()));
  };
  // the cube's top face, beside the cloth: lit green, one flat shade (its two triangles and
  // their shared diagonal alike), and no edge lines on it
  const Eigen::Vector3f top = at(image, {0.35, 0.0, -0.05});
  EXPECT_GT(top.y(), 1.5f * top.x()) << top.transpose();
  EXPECT_GT(top.y(), 1.5f * top.z()) << top.transpose();
  EXPECT_LT(color_distance(top, options.obstacle_color), 0.3f) << top.transpose();
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0.3, -0.2, -0.05),
                                   {0.45, 0.2, -0.05},
                                   {0.25, 0.0, -0.05},
                                   {0.4, 0.15, -0.05}})
    EXPECT_LT(color_distance(at(image, p), top), 0.01f) << p.transpose();
  float largest_change = 0.0f;
  for (double y = -0.2; y <= 0.2; y += 0.02)
    for (double x = 0.22; x <= 0.48; x += 0.02)
      largest_change = std::max(
          largest_change, color_distance(at(image, {x, y, -0.05}), at(unwired, {x, y, -0.05})));
  EXPECT_LT(largest_change, 0.01f);
  // where the cloth covers the cube, the cloth shows
  const Eigen::Vector3f covered = at(image, {0.12, 0.07, 0.0});
  EXPECT_LT(color_distance(covered, options.front_color),
            color_distance(covered, options.obstacle_color))
      << covered.transpose();
}

TEST(Renderer, GivesTheSameImageTwiceAndAnEmptyMeshShowsOnlyTheBackground) {
  Renderer renderer(small_options());
  const IndexedMesh mesh = test::square_mesh(1.0, 3, false);
  const Image first = renderer.render(test::scene_of(mesh), square_camera());
  EXPECT_EQ(first.rgb, renderer.render(test::scene_of(mesh), square_camera()).rgb);
  const IndexedMesh empty;
  const Image blank = renderer.render(test::scene_of(empty), square_camera());
  EXPECT_EQ(pixels_unlike(blank, renderer.options().background_color, 1.5f / 255), 0);
}

TEST(Renderer, RejectsABrokenCameraAndBadOptions) {
  Renderer renderer(small_options());
  const IndexedMesh mesh = test::square_mesh(1.0, 1);
  Camera camera = square_camera();
  camera.fov_y_deg = 0.0;
  EXPECT_THROW(renderer.render(test::scene_of(mesh), camera), std::invalid_argument);
  RenderOptions odd = small_options();
  odd.height = 121;
  EXPECT_THROW(Renderer{odd}, std::invalid_argument);
}

}  // namespace
}  // namespace tissu
