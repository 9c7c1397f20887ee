// Runs that blow up stop at the step where it starts, with a last good state that is still
// physical; stable runs of every kind of scene do not trip the check.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lib/mesh_io/read_mesh.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

constexpr double gravity_m_per_s2 = 9.81;

struct RunRecord {
  RunResult result;
  std::vector<FrameStats> frames;
  std::filesystem::path dir;
};

RunRecord run(const Scenario& scenario, const std::string& name, int frames) {
  RunRecord out;
  out.dir = test::fresh_temp_dir(name);
  RunOptions options;
  options.output_dir = out.dir;
  options.frames = frames;
  options.on_frame = [&](const FrameStats& s) { out.frames.push_back(s); };
  out.result = run_scenario(scenario, options);
  return out;
}

/// The bounding box of a mesh file's vertices (m).
Eigen::AlignedBox3d bounds_of(const std::filesystem::path& file) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : read_mesh(file).vertices) box.extend(p);
  return box;
}

/// Whether `inner` lies inside `outer` grown by `margin_m` on every side.
bool inside(const Eigen::AlignedBox3d& inner, const Eigen::AlignedBox3d& outer, double margin_m) {
  Eigen::AlignedBox3d grown = outer;
  grown.min().array() -= margin_m;
  grown.max().array() += margin_m;
  return grown.contains(inner);
}

/// No recorded frame holds more kinetic energy than the cloth's whole mass falling freely since
/// the start, 1/2 M (g t)^2 (J): what a pinned cloth released from rest can have at most.
void expect_free_fall_energy_at_most(const std::vector<FrameStats>& frames) {
  for (const FrameStats& f : frames) {
    const double free_fall_j = 0.5 * f.total_mass * std::pow(gravity_m_per_s2 * f.time, 2);
    EXPECT_LE(f.kinetic_energy, 1.0001 * free_fall_j) << "frame " << f.frame;
  }
}

TEST(DivergenceRun, TheHangingSheetWithSymplecticEulerStopsAtItsFirstExplodedFrame) {
  // Liu et al.'s stiff sheet at one explicit step per frame: after frame 1 it has fallen g h^2
  // (KE 0.05 J); the next step launches the particles beside the pins at thousands of m/s. The
  // run used to go on until inf, 5 frames here (40 in issue 17's run), and write an exploded
  // "last good" frame.
  const Scenario scenario = load_scenario(
      TISSU_DATA_DIR "/scenarios/hanging_sheet.json",
      {"simulation.integrator=symplectic_euler", "render.enabled=false", "output.mesh_every=1"});
  const RunRecord r = run(scenario, "divergence_sheet", 60);
  ASSERT_FALSE(r.result.ok);
  EXPECT_EQ(r.result.frames_done, 1);
  EXPECT_THAT(r.result.failure, HasSubstr("frame 2, step 1 of 1"));
  EXPECT_THAT(r.result.failure, HasSubstr("moves at"));
  EXPECT_THAT(r.result.failure, HasSubstr("last_good_frame_00001.obj"));
  expect_free_fall_energy_at_most(r.frames);

  // the last good frame is frame 1: the sheet where it was, at most g h^2 lower (one explicit
  // step falls by h (g h))
  const double h = 1.0 / 30.0;
  const Eigen::AlignedBox3d start = bounds_of(r.dir / "frame_00000.obj");
  const Eigen::AlignedBox3d last_good = bounds_of(r.dir / "last_good_frame_00001.obj");
  EXPECT_TRUE(inside(last_good, start, gravity_m_per_s2 * h * h + 1e-4))
      << last_good.min().transpose() << " .. " << last_good.max().transpose();
  EXPECT_EQ(read_mesh(r.dir / "last_good_frame_00001.obj").vertices.size(),
            read_mesh(r.dir / "frame_00000.obj").vertices.size());
}

TEST(DivergenceRun, AStiffExplicitClothStopsAtTheStepWhereItBlowsUpAndKeepsTheStepBefore) {
  // 100 kN/m springs on 0.1 g particles at h = 1/600 s: h omega is about 50, and the second step
  // already multiplies the first one's speeds (g h, 16 mm/s) by thousands
  const Scenario scenario = parse_scenario(R"({
    "cloth": { "grid": { "size": [1, 1], "resolution": [8, 8] }, "density": 0.01,
               "springs": { "structural": { "stiffness": 100000 } } },
    "pins": [ { "side": "top" } ],
    "simulation": { "integrator": "symplectic_euler", "frames": 30, "substeps": 20 }
  })",
                                           "stiff.json");
  const RunRecord r = run(scenario, "divergence_stiff", 30);
  ASSERT_FALSE(r.result.ok);
  EXPECT_EQ(r.result.frames_done, 0);
  EXPECT_THAT(r.result.failure, HasSubstr("frame 1, step 2 of 20"));
  EXPECT_THAT(r.result.failure, HasSubstr("last_good_frame_00000_step_01.obj"));
  const double h = 1.0 / 600.0;
  const Eigen::AlignedBox3d start = bounds_of(r.dir / "frame_00000.obj");
  EXPECT_TRUE(inside(bounds_of(r.dir / "last_good_frame_00000_step_01.obj"), start,
                     gravity_m_per_s2 * h * h + 1e-6));
}

TEST(DivergenceRun, ADivergingVerletRunWritesNoNonFiniteOrExplodedCoordinate) {
  // issue 18: position Verlet on springs far too stiff for its step used to write frames and a
  // last good frame of inf coordinates (and stats rows of inf); every file it writes now holds
  // finite positions near the start, and every stats.csv value is finite
  const Scenario scenario = parse_scenario(R"({
    "cloth": { "grid": { "size": [1, 1], "resolution": [8, 8] }, "density": 0.01,
               "springs": { "structural": { "stiffness": 100000 } } },
    "pins": [ { "side": "top" } ],
    "simulation": { "integrator": "position_verlet", "frames": 200, "substeps": 1 }
  })",
                                           "verlet.json");
  const RunRecord r = run(scenario, "divergence_verlet", 200);
  ASSERT_FALSE(r.result.ok);
  EXPECT_THAT(r.result.failure, HasSubstr("last_good_frame_"));
  const Eigen::AlignedBox3d start = bounds_of(r.dir / "frame_00000.obj");
  int meshes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(r.dir)) {
    if (entry.path().extension() != ".obj") continue;
    ++meshes;
    for (const Eigen::Vector3d& p : read_mesh(entry.path()).vertices) {
      ASSERT_TRUE(p.allFinite()) << entry.path();
    }
    // nothing exploded: within a metre of where the sheet started
    EXPECT_TRUE(inside(bounds_of(entry.path()), start, 1.0)) << entry.path();
  }
  EXPECT_EQ(meshes, r.result.frames_done + 2);  // frames 0..done and the last good state
  std::ifstream csv(r.dir / "stats.csv");
  std::string line;
  std::getline(csv, line);  // the header
  int rows = 0;
  for (; std::getline(csv, line); ++rows) {
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) {
      EXPECT_TRUE(std::isfinite(std::stod(field))) << "row " << rows << ": " << line;
    }
  }
  EXPECT_EQ(rows, r.result.frames_done + 1);
}

TEST(DivergenceRun, StableScenesOfEveryKindRunToTheirEnd) {
  // what the limit has to allow: an explicit cloth swinging freely, handles pulling a strip until
  // it tears and recoils, a keyframed ball pushed through a pinned sheet, a gathered curtain in
  // gusty wind, at the step sizes the shipped scenarios use
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {"swinging", R"({
        "cloth": { "grid": { "size": [1, 1], "resolution": [10, 10] }, "density": 0.2,
                   "springs": { "structural": { "stiffness": 500, "damping": 0.1 } } },
        "pins": [ { "corners": ["top_left"] } ],
        "simulation": { "integrator": "position_verlet", "frames": 45, "substeps": 40 } })"},
      {"torn", R"({
        "cloth": { "grid": { "size": [0.2, 1.0], "resolution": [4, 20] }, "density": 0.2,
                   "springs": { "structural": { "stiffness": 500, "damping": 0.2 } } },
        "pins": [ { "side": "bottom", "velocity": [0, 0, -0.1] },
                  { "side": "top", "velocity": [0, 0, 0.1] } ],
        "environment": { "gravity": [0, 0, 0] },
        "tearing": { "strain": 0.15 },
        "simulation": { "integrator": "symplectic_euler", "frames": 45, "substeps": 100 } })"},
      {"ball", R"({
        "cloth": { "grid": { "size": [1, 1], "resolution": [12, 12], "cells": "triangles",
                             "origin": [-0.5, -0.5, 0.5], "u_axis": [1, 0, 0], "v_axis": [0, 1, 0] },
                   "density": 0.2,
                   "springs": { "structural": { "stiffness": 1000, "damping": 0.5 } } },
        "pins": [ { "side": "left" }, { "side": "right" } ],
        "obstacles": [ { "type": "sphere", "center": [0, 0, 0.7], "radius": 0.1,
                         "motion": { "keyframes": [ { "time": 0, "offset": [0, 0, 0] },
                                                    { "time": 0.5, "offset": [0, 0, -0.6] } ] } } ],
        "simulation": { "integrator": "implicit_euler", "frames": 30, "substeps": 10 } })"},
      {"curtain", R"({
        "cloth": { "grid": { "size": [2.0, 2.4], "resolution": [10, 12], "cells": "triangles",
                             "pleats": { "count": 5, "gathered_width": 1.4 },
                             "u_axis": [1, 0, 0], "v_axis": [0, 0, 1] },
                   "density": 0.2,
                   "springs": { "structural": { "stiffness": 1000, "damping": 0.5 },
                                "bending": { "stiffness": 4, "damping": 0.02 } } },
        "pins": [ { "side": "top", "every": 2 } ],
        "environment": { "wind": { "velocity": [0, 0.8, 0], "gust_amplitude": 0.8,
                                   "gust_frequency": 0.4 } },
        "simulation": { "integrator": "quasi_newton", "frames": 45, "substeps": 1 } })"},
  };
  for (const auto& [name, json] : scenes) {
    const Scenario scenario = parse_scenario(json, name + ".json", {"output.meshes=false"});
    const RunRecord r = run(scenario, "stable_" + name, scenario.frames);
    EXPECT_TRUE(r.result.ok) << name << ": " << r.result.failure;
    EXPECT_EQ(r.result.frames_done, scenario.frames) << name;
  }
}

}  // namespace
}  // namespace tissu
