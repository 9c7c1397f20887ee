// frames.pc2 plays the run on the frame-0 mesh: one sample per frame, point k is vertex k of the
// frame meshes; refused where the particles change.

#include "lib/point_cache.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "lib/mesh_io/read_mesh.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct Pc2 {
  std::string signature;
  std::int32_t version = 0, points = 0, samples = 0;
  float start_frame = 0, sample_rate = 0;
  std::vector<float> xyz;  ///< samples x points x 3
};

Pc2 read_pc2(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Pc2 pc2;
  if (bytes.size() < 32) return pc2;
  pc2.signature = bytes.substr(0, 12);
  std::memcpy(&pc2.version, bytes.data() + 12, 4);
  std::memcpy(&pc2.points, bytes.data() + 16, 4);
  std::memcpy(&pc2.start_frame, bytes.data() + 20, 4);
  std::memcpy(&pc2.sample_rate, bytes.data() + 24, 4);
  std::memcpy(&pc2.samples, bytes.data() + 28, 4);
  pc2.xyz.resize((bytes.size() - 32) / 4);
  std::memcpy(pc2.xyz.data(), bytes.data() + 32, pc2.xyz.size() * 4);
  return pc2;
}

const char* const hanging_sheet = R"({
  "cloth": { "grid": { "size": [0.5, 0.5], "resolution": [6, 6], "origin": [0, 0, 1],
                       "u_axis": [1, 0, 0], "v_axis": [0, 0, 1] },
             "density": 0.2, "springs": { "structural": { "stiffness": 200, "damping": 0.1 } } },
  "pins": [ { "side": "top" } ],
  "simulation": { "frames": 5, "substeps": 5 },
  "output": { "mesh_every": 5 }
})";

TEST(PointCache, HoldsEveryFrameOfTheRunAsItsMeshesDo) {
  const fs::path dir = test::fresh_dir_for_this_test("point_cache");
  RunOptions options;
  options.output_dir = dir;
  ASSERT_TRUE(run_scenario(parse_scenario(hanging_sheet, dir / "sheet.json"), options).ok);
  const Pc2 pc2 = read_pc2(dir / "frames.pc2");
  EXPECT_EQ(pc2.signature, std::string("POINTCACHE2", 12));
  EXPECT_EQ(pc2.version, 1);
  EXPECT_EQ(pc2.points, 49);
  EXPECT_EQ(pc2.start_frame, 0.0f);
  EXPECT_EQ(pc2.sample_rate, 1.0f);
  ASSERT_EQ(pc2.samples, 6);  // frames 0 to 5, though meshes are written for 0 and 5 only
  ASSERT_EQ(pc2.xyz.size(), 6u * 49u * 3u);
  for (int frame : {0, 5}) {
    const IndexedMesh mesh = read_mesh(dir / ("frame_0000" + std::to_string(frame) + ".obj"));
    ASSERT_EQ(mesh.vertices.size(), 49u);
    for (int k = 0; k < 49; ++k) {
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_FLOAT_EQ(pc2.xyz[(frame * 49 + k) * 3 + axis], mesh.vertices[k][axis])
            << "frame " << frame << ", point " << k;
      }
    }
  }
  EXPECT_NE(pc2.xyz[5 * 49 * 3 + 2], pc2.xyz[2]);  // the sheet moved
}

TEST(PointCache, IsNotWrittenWhereTheParticlesChange) {
  const std::string adaptive = std::string(hanging_sheet)
                                   .replace(std::string(hanging_sheet).rfind('}'), 1,
                                            R"(, "adaptive": { "curvature": 0.5 } })");
  const fs::path dir = test::fresh_dir_for_this_test("point_cache");
  const Scenario scenario = parse_scenario(adaptive, dir / "sheet.json");
  EXPECT_FALSE(scenario.output.point_cache);
  try {
    parse_scenario(adaptive, dir / "sheet.json", {"output.point_cache=true"});
    ADD_FAILURE() << "a point cache of an adaptive run was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), HasSubstr("sheet.json: output.point_cache: expected false with "
                                    "adaptive refinement or tearing"));
  }
}

TEST(PointCache, RefusesASampleOfAnotherSize) {
  const fs::path dir = test::fresh_dir_for_this_test("point_cache");
  PointCacheFile cache(dir / "frames.pc2", 2);
  cache.append(Eigen::VectorXd::Zero(6));
  EXPECT_THROW(cache.append(Eigen::VectorXd::Zero(9)), std::invalid_argument);
  EXPECT_EQ(cache.samples(), 1);
  EXPECT_EQ(read_pc2(dir / "frames.pc2").samples, 1);
}

}  // namespace
}  // namespace tissu
