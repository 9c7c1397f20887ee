// Self-collision and cuts: the two lips of a fresh cut or tear are one piece of cloth, not two
// layers in contact, so they open as they do without self-collision; pieces that later meet
// collide.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/lib/face_intersections.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

/// A 0.4 m square sheet of 0.02 m cells in the x-z plane, z from 0.3 m to 0.7 m, hanging from
/// pins along its top side, then cut along each of `cuts` ({time (s), height z (m)}) across its
/// whole width.
std::string cut_hanging_sheet(const std::vector<std::pair<double, double>>& cuts, int frames,
                              const std::string& extra) {
  std::string cut_list;
  for (const auto& [time_s, z_m] : cuts) {
    const std::string z = std::to_string(z_m);
    cut_list += std::string(cut_list.empty() ? "" : ", ") + R"({ "time": )" +
                std::to_string(time_s) + R"(, "line": [[-0.3, 0, )" + z + R"(], [0.3, 0, )" + z +
                "]] }";
  }
  return R"({
  "cloth": { "grid": { "size": [0.4, 0.4], "resolution": [20, 20], "cells": "triangles",
                       "origin": [-0.2, 0, 0.3], "u_axis": [1, 0, 0], "v_axis": [0, 0, 1] },
             "density": 0.2,
             "springs": { "structural": { "stiffness": 1000, "damping": 0.5 },
                          "bending": { "stiffness": 1, "damping": 0.01 } } },
  "pins": [ { "side": "top" } ],
  "environment": { "air_damping": 0.2 },
  "tearing": { "cuts": [ )" +
         cut_list + R"( ] },
  "simulation": { "frames": )" +
         std::to_string(frames) + R"(, "substeps": 10 },
  "output": { "meshes": false })" +
         extra + "\n}";
}

const std::string with_self_collision =
    R"(, "self_collision": { "thickness": 0.004, "friction": 0.1 })";

struct CutRun {
  RunResult result;
  std::vector<FrameStats> frames;
  std::vector<MaterialSurface> surfaces;  // every frame's
};

CutRun run(const std::string& json, const std::string& name) {
  CutRun out;
  RunOptions options;
  options.output_dir = test::fresh_temp_dir(name);
  options.on_frame = [&](const FrameStats& s) { out.frames.push_back(s); };
  options.on_surface = [&](int, const MaterialSurface& s) { out.surfaces.push_back(s); };
  out.result = run_scenario(parse_scenario(json, name + ".json"), options);
  return out;
}

TEST(CutWithSelfCollision, TheLowerHalfFallsAwayAsItDoesWithoutSelfCollision) {
  const CutRun without = run(cut_hanging_sheet({{0.1, 0.5}}, 15, ""), "cut_alone");
  const CutRun with =
      run(cut_hanging_sheet({{0.1, 0.5}}, 15, with_self_collision), "cut_self_collision");
  ASSERT_TRUE(without.result.ok) << without.result.failure;
  ASSERT_TRUE(with.result.ok) << with.result.failure;
  ASSERT_EQ(with.frames.size(), without.frames.size());
  for (const FrameStats& f : with.frames) EXPECT_EQ(f.self_contacts, 0) << "frame " << f.frame;
  EXPECT_EQ(with.frames.back().pieces, 2);
  // the lips never touched: the runs are the same to round-off
  const IndexedMesh& a = with.surfaces.back().current;
  const IndexedMesh& b = without.surfaces.back().current;
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    EXPECT_LT((a.vertices[v] - b.vertices[v]).norm(), 1e-9) << "vertex " << v;
  }
  // and the lower half fell: 0.4 s of free fall is 0.78 m
  double lowest_z = 1.0;
  for (const Eigen::Vector3d& x : a.vertices) lowest_z = std::min(lowest_z, x.z());
  EXPECT_LT(lowest_z, 0.3 - 0.5);
}

TEST(CutWithSelfCollision, PiecesThatMeetAfterTheCutDoNotPassThroughEachOther) {
  // cut across the middle at once: the lower half falls onto the floor and crumples; cut again
  // just below the pins at 0.5 s: the upper half falls onto it
  const std::string floor =
      R"(, "obstacles": [ { "type": "plane", "static_friction": 0.5, "kinetic_friction": 0.4 } ])";
  const CutRun r =
      run(cut_hanging_sheet({{0.0, 0.5}, {0.5, 0.67}}, 36, with_self_collision + floor),
          "cut_pieces_meet");
  ASSERT_TRUE(r.result.ok) << r.result.failure;
  EXPECT_EQ(r.frames.back().pieces, 3);  // the strip on the pins, and the two halves
  // they met: at some frame, particles of the upper half (material z between the cuts) lie within
  // 1 cm of particles of the lower half (35 to 42 of them as it lands; where it then comes to rest,
  // on the lower half or beside it, varies with the solver's round-off)
  int most_close = 0;
  for (std::size_t f = 0; f < r.surfaces.size(); ++f) {
    const MaterialSurface& surface = r.surfaces[f];
    EXPECT_EQ(test::intersecting_face_pairs(surface), 0) << "frame " << f;
    int close = 0;
    for (std::size_t u = 0; u < surface.rest_m.size(); ++u) {
      const double z = surface.rest_m[u].z();
      if (!(z > 0.5 + 1e-9 && z < 0.66)) continue;
      for (std::size_t l = 0; l < surface.rest_m.size(); ++l) {
        if (surface.rest_m[l].z() < 0.5 - 1e-9 &&
            (surface.current.vertices[u] - surface.current.vertices[l]).norm() < 0.01) {
          ++close;
          break;
        }
      }
    }
    most_close = std::max(most_close, close);
  }
  EXPECT_GT(most_close, 10);
}

TEST(CutWithSelfCollision, TheTearingDemoTearsAsItDoesWithoutSelfCollision) {
  const std::filesystem::path demo = TISSU_DATA_DIR "/scenarios/tearing.json";
  const auto tears_of = [&](const std::vector<std::string>& overrides, const std::string& name) {
    RunOptions options;
    options.output_dir = test::fresh_temp_dir(name);
    options.frames = 40;  // the crack starts at frame 21 and parts the sheet by frame 30
    std::vector<FrameStats> frames;
    options.on_frame = [&](const FrameStats& s) { frames.push_back(s); };
    std::vector<std::string> all = {"render.enabled=false", "output.meshes=false"};
    all.insert(all.end(), overrides.begin(), overrides.end());
    const RunResult result = run_scenario(load_scenario(demo, all), options);
    EXPECT_TRUE(result.ok) << result.failure;
    return frames;
  };
  const std::vector<FrameStats> with = tears_of({}, "tearing_demo_self_collision");
  const std::vector<FrameStats> without =
      tears_of({"self_collision.enabled=false"}, "tearing_demo_alone");
  ASSERT_EQ(with.size(), without.size());
  int tears_with = 0, tears_without = 0;
  for (std::size_t f = 0; f < with.size(); ++f) {
    tears_with += with[f].tears;
    tears_without += without[f].tears;
    EXPECT_NEAR(with[f].tears, without[f].tears, 2) << "frame " << f;
    EXPECT_EQ(with[f].pieces, without[f].pieces) << "frame " << f;
  }
  EXPECT_NEAR(tears_with, tears_without, 3);
  EXPECT_GT(tears_without, 10);
  EXPECT_EQ(with.back().pieces, 2);
}

}  // namespace
}  // namespace tissu
