// Animated mesh obstacles in a scenario: a PC2 point cache or keyframe meshes, placed like the
// mesh file, drawn where they are, and every way of giving them wrong named.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "lib/mesh_io/write_mesh.hpp"
#include "lib/obstacle_mesh.hpp"
#include "lib/point_cache.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/lib/scenario_errors.hpp"
#include "tests/test_meshes.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

/// The cube [-1, 1]^3 (8 vertices, 12 triangles, closed).
IndexedMesh cube() {
  return test::cube_mesh(Eigen::Vector3d::Zero(), 1.0);
}

/// A closed tetrahedron, facing outwards.
IndexedMesh tetrahedron() {
  IndexedMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return m;
}

/// `mesh`'s positions moved by `offset`, flattened as a cache sample.
Eigen::VectorXd sample(const IndexedMesh& mesh, const Eigen::Vector3d& offset) {
  Eigen::VectorXd x(3 * mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    x.segment<3>(3 * v) = mesh.vertices[v] + offset;
  return x;
}

/// A folder holding cube.obj and cube.pc2, the cube moving +1 m in x per sample, 3 samples.
fs::path cube_with_cache() {
  const fs::path dir = test::fresh_dir_for_this_test("animated_obstacle");
  write_mesh(dir / "cube.obj", cube(), MeshFormat::obj);
  PointCacheFile cache(dir / "cube.pc2", 8);
  for (int k = 0; k < 3; ++k) cache.append(sample(cube(), {1.0 * k, 0.0, 0.0}));
  return dir;
}

Scenario with_obstacle(const std::string& obstacle) {
  return parse_scenario(test::minimal_scenario, "dir/s.json", {"obstacles=[" + obstacle + "]"});
}

std::string error_with_obstacle(const std::string& obstacle) {
  return test::scenario_error_of(test::minimal_scenario, {"obstacles=[" + obstacle + "]"});
}

TEST(PointCache, ReadsBackWhatItWrites) {
  const fs::path dir = cube_with_cache();
  const PointCache cache = read_point_cache(dir / "cube.pc2");
  EXPECT_EQ(cache.start_frame, 0.0);
  EXPECT_EQ(cache.sample_rate, 1.0);
  ASSERT_EQ(cache.samples.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(cache.samples[k].size(), 8u);
    for (int v = 0; v < 8; ++v) {
      EXPECT_EQ(cache.samples[k][v], cube().vertices[v] + Eigen::Vector3d(k, 0, 0));
    }
  }
}

/// `bytes` of the cache of cube_with_cache() changed by `edit`, read back: the error.
template <class Edit>
std::string error_of_edited_cache(Edit edit) {
  const fs::path file = cube_with_cache() / "cube.pc2";
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  edit(bytes);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  try {
    read_point_cache(file);
  } catch (const PointCacheError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PointCache, RefusesAFileOverItsSizeLimitBeforeReadingIt) {
  const fs::path file = cube_with_cache() / "cube.pc2";  // 320 bytes
  try {
    read_point_cache(file, 319);
    FAIL() << "accepted";
  } catch (const PointCacheError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cube.pc2: 320 bytes, over the limit of 319"));
  }
  EXPECT_EQ(read_point_cache(file, 320).samples.size(), 3u);
}

TEST(PointCache, RefusesABrokenFileNamingWhatIsWrong) {
  EXPECT_THAT(error_of_edited_cache([](std::string& b) { b[0] = 'X'; }),
              HasSubstr("cube.pc2: not a PC2 file"));
  EXPECT_THAT(error_of_edited_cache([](std::string& b) { b.resize(20); }),
              HasSubstr("not a PC2 file"));
  EXPECT_THAT(error_of_edited_cache([](std::string& b) { b[12] = 2; }),
              HasSubstr("version 2; expected 1"));
  EXPECT_THAT(
      error_of_edited_cache([](std::string& b) { b.resize(b.size() - 1); }),
      HasSubstr("its header counts 3 samples of 8 points (320 bytes), but the file has 319"));
  // counts whose product of bytes passes 2^64 (12 (2^31 - 1)^2 = 3 2^64 - 12 2^32 + 12)
  EXPECT_THAT(error_of_edited_cache([](std::string& b) {
                const std::int32_t most = 0x7fffffff;
                std::memcpy(&b[16], &most, 4);  // points
                std::memcpy(&b[28], &most, 4);  // samples
              }),
              HasSubstr("its header counts 2147483647 samples of 2147483647 points "
                        "(55340232169589047340 bytes), but the file has 320"));
  EXPECT_THAT(error_of_edited_cache([](std::string& b) { std::fill_n(&b[16], 4, '\xff'); }),
              HasSubstr("-1 points and 3 samples; expected at least one of each"));
  EXPECT_THAT(error_of_edited_cache([](std::string& b) {
                const float nan = NAN;
                std::memcpy(&b[32 + 12 * 8 + 4], &nan, 4);  // sample 1, point 0, y
              }),
              HasSubstr("sample 1, point 0: a non-finite coordinate"));
  EXPECT_THAT(error_of_edited_cache([](std::string& b) { std::fill_n(&b[24], 4, '\0'); }),
              HasSubstr("sample rate 0.000000; expected"));
}

TEST(AnimatedObstacle, FollowsItsPointCachePlacedLikeItsMesh) {
  // samples at 0.5, 0.6 and 0.7 s (10 frames per second from 0.5 s), scaled by a half and raised
  // by 1 m like the mesh file: the cube of half-side 0.5 moves +0.5 m per sample
  const fs::path dir = cube_with_cache();
  const Scenario s =
      with_obstacle(R"({ "type": "mesh", "file": ")" + (dir / "cube.obj").string() +
                    R"(", "scale": 0.5, "position": [0, 0, 1],
      "animation": { "point_cache": ")" +
                    (dir / "cube.pc2").string() + R"(", "frame_rate": 10, "start_time": 0.5 } })");
  const Obstacle& o = s.solver.obstacles.at(0);
  ASSERT_TRUE(o.animation);
  const Eigen::Vector3d x(3.0, 0.0, 1.0);
  EXPECT_NEAR(surface_distance(o, x, 0.0).distance_m, 2.5, 1e-6);  // held before the first
  EXPECT_NEAR(surface_distance(o, x, 0.55).distance_m, 2.25, 1e-6);
  EXPECT_NEAR(surface_distance(o, x, 0.7).distance_m, 1.5, 1e-6);
  EXPECT_NEAR(surface_distance(o, x, 9.0).distance_m, 1.5, 1e-6);         // and after the last
  EXPECT_NEAR(o.animation->fastest_speed_m_per_s(), 5.0, 1e-6);           // 0.5 m in 0.1 s
  for (const Eigen::Vector3d& corner : obstacle_mesh(o, 0.6).vertices) {  // drawn where it is
    EXPECT_NEAR(std::abs(corner.x() - 0.5), 0.5, 1e-6);
    EXPECT_NEAR(std::abs(corner.z() - 1.0), 0.5, 1e-6);
  }
}

TEST(AnimatedObstacle, FollowsItsKeyframeMeshes) {
  const fs::path dir = test::fresh_dir_for_this_test("animated_obstacle");
  IndexedMesh moved = cube();
  for (Eigen::Vector3d& v : moved.vertices) v *= 2.0;
  write_mesh(dir / "small.obj", cube(), MeshFormat::obj);
  write_mesh(dir / "large.obj", moved, MeshFormat::obj);
  const Scenario s = with_obstacle(R"({ "type": "mesh", "file": ")" + (dir / "small.obj").string() +
                                   R"(", "animation": { "keyframes": [
      { "time": 1, "file": ")" + (dir / "small.obj").string() +
                                   R"(" },
      { "time": 2, "file": ")" + (dir / "large.obj").string() +
                                   R"(" } ] } })");
  const Obstacle& o = s.solver.obstacles.at(0);
  const Eigen::Vector3d x(3.0, 0.0, 0.0);
  EXPECT_NEAR(surface_distance(o, x, 1.0).distance_m, 2.0, 1e-12);
  EXPECT_NEAR(surface_distance(o, x, 1.5).distance_m, 1.5, 1e-12);
  EXPECT_NEAR(surface_distance(o, x, 2.0).distance_m, 1.0, 1e-12);
}

TEST(AnimatedObstacle, BadAnimationsAreNamed) {
  const fs::path dir = cube_with_cache();
  const std::string mesh =
      R"({ "type": "mesh", "file": ")" + (dir / "cube.obj").string() + R"(", )";
  const std::string cache = (dir / "cube.pc2").string();
  EXPECT_THAT(error_with_obstacle(mesh + R"("animation": {} })"),
              HasSubstr("obstacles[0].animation.point_cache: expected exactly one of "
                        "\"point_cache\" or \"keyframes\""));
  EXPECT_THAT(error_with_obstacle(mesh + R"("animation": { "point_cache": ")" + cache + R"(" } })"),
              HasSubstr("obstacles[0].animation.frame_rate: missing; expected a number between"));
  EXPECT_THAT(error_with_obstacle(mesh + R"("animation": { "point_cache": "none.pc2",
                                                          "frame_rate": 30 } })"),
              HasSubstr("dir/s.json: obstacles[0].animation.point_cache: point cache "
                        "dir/none.pc2: cannot be opened"));
  EXPECT_THAT(error_with_obstacle(mesh + R"("animation": { "point_cache": ")" + cache +
                                  R"(", "frame_rate": 30, "strat_time": 1 } })"),
              HasSubstr("did you mean 'start_time'?"));
  // a cache of another mesh
  PointCacheFile other(dir / "other.pc2", 5);
  other.append(Eigen::VectorXd::Zero(15));
  EXPECT_THAT(error_with_obstacle(mesh + R"("animation": { "point_cache": ")" +
                                  (dir / "other.pc2").string() + R"(", "frame_rate": 30 } })"),
              HasSubstr("obstacles[0].animation.point_cache: expected a cache of one point per "
                        "vertex of the mesh file (8), not 5"));
  // keyframes out of order, and of another mesh
  write_mesh(dir / "tetra.obj", tetrahedron(), MeshFormat::obj);
  const std::string cube_file = (dir / "cube.obj").string();
  EXPECT_THAT(error_with_obstacle(mesh + R"("animation": { "keyframes": [
      { "time": 1, "file": ")" + cube_file +
                                  R"(" }, { "time": 1, "file": ")" + cube_file + R"(" } ] } })"),
              HasSubstr("obstacles[0].animation.keyframes[1].time: expected a time after the "
                        "previous keyframe's"));
  EXPECT_THAT(error_with_obstacle(mesh + R"("animation": { "keyframes": [
      { "time": 1, "file": ")" + (dir / "tetra.obj").string() +
                                  R"(" } ] } })"),
              HasSubstr("obstacles[0].animation.keyframes[0].file: expected a mesh with the mesh "
                        "file's 8 vertices, in its order, not 4"));
}

TEST(MeshObstacle, ASoupOfPartsIsResolvedPartByPart) {
  // a torso (the cube) and an arm sunk 0.5 m into it, [0.5, 3] x [-0.2, 0.2]^2: one obstacle per
  // part, so that a point inside the torso is led out of the torso, not to the arm's buried end
  const fs::path dir = test::fresh_dir_for_this_test("mesh_obstacle");
  IndexedMesh soup = cube();
  const IndexedMesh arm = test::cube_mesh({1.75, 0.0, 0.0}, 1.0);
  for (const Eigen::Vector3d& v : arm.vertices) {
    soup.vertices.push_back({1.75 + 1.25 * (v.x() - 1.75), 0.2 * v.y(), 0.2 * v.z()});
  }
  for (std::vector<int> f : arm.faces) {
    for (int& v : f) v += 8;
    soup.faces.push_back(f);
  }
  write_mesh(dir / "body.obj", soup, MeshFormat::obj);
  const Scenario s = with_obstacle(R"({ "type": "mesh", "file": ")" + (dir / "body.obj").string() +
                                   R"(", "static_friction": 0.3, "motion": { "keyframes": [
      { "time": 0 }, { "time": 1, "rotation": { "degrees": 90 } } ] } })");
  ASSERT_EQ(s.solver.obstacles.size(), 2u);
  const Eigen::Vector3d inside_torso(0.45, 0.0, 0.0);  // 0.05 m from the arm's buried end
  EXPECT_NEAR(surface_distance(s.solver.obstacles[0], inside_torso, 0.0).distance_m, -0.55, 1e-12);
  EXPECT_GT(surface_distance(s.solver.obstacles[1], inside_torso, 0.0).distance_m, 0.0);
  for (const Obstacle& part : s.solver.obstacles) {
    EXPECT_EQ(part.static_friction, 0.3);
    // both turn about the whole mesh's centre, the mean of all its triangle corners
    EXPECT_TRUE(part.motion.pivot_m.isApprox(s.solver.obstacles[0].motion.pivot_m));
  }
  EXPECT_GT(s.solver.obstacles[0].motion.pivot_m.x(), 0.5);
}

TEST(AnimatedObstacle, VerticesTheMeshFileJoinsMustMoveTogether) {
  // two triangles with a corner each at the origin, as two file vertices: the reader joins them,
  // and a cache that moves them apart cannot be followed
  const fs::path dir = test::fresh_dir_for_this_test("animated_obstacle");
  std::ofstream(dir / "bow.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv -1 0 0\nv -1 -1 0\n"
                                    "f 1 2 3\nf 4 5 6\n";
  PointCacheFile cache(dir / "bow.pc2", 6);
  Eigen::VectorXd x(18);
  x << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, -1, 0, 0, -1, -1, 0;
  cache.append(x);
  x[11] = 0.5;  // the second corner at the origin rises
  cache.append(x);
  EXPECT_THAT(error_with_obstacle(R"({ "type": "mesh", "file": ")" + (dir / "bow.obj").string() +
                                  R"(", "animation": { "point_cache": ")" +
                                  (dir / "bow.pc2").string() + R"(", "frame_rate": 30 } })"),
              HasSubstr("obstacles[0].animation: sample 1: the file's vertices 0 and 3 are at the "
                        "same place in the mesh file"));
}

}  // namespace
}  // namespace tissu
