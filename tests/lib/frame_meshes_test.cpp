// The meshes a run writes are the simulation: every particle in particle order, to the last bit,
// the faces as simulated and the rest coordinates, after refinement and after a knife cut.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <string>

#include "lib/mesh_io/read_obj.hpp"
#include "lib/mesh_io/write_mesh.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/lib/written_ply.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

/// A 0.4 m x 0.4 m sheet hanging from its top side, stepped for 3 frames; `extra` adds sections.
std::string hanging_sheet(const std::string& cells, const std::string& format,
                          const std::string& extra) {
  return R"({
  "cloth": { "grid": { "size": [0.4, 0.4], "resolution": [4, 4], "cells": ")" +
         cells + R"(" },
             "density": 0.2,
             "springs": { "structural": { "stiffness": 200, "damping": 0.1 } } },
  "pins": [ { "side": "top" } ],
  "simulation": { "frames": 3, "substeps": 5 },
  "output": { "mesh_format": ")" +
         format + R"(" })" + extra + R"(
})";
}

/// What a run wrote and what the model was, frame by frame.
struct Recorded {
  std::filesystem::path dir;
  std::vector<FrameStats> stats;
  std::vector<MaterialSurface> surfaces;  ///< the model's particles and faces, per frame
  ClothFrame frame;
};

Recorded run(const std::string& scenario_json, const std::string& name) {
  Recorded out;
  RunOptions options;
  options.output_dir = out.dir = test::fresh_temp_dir("frame_meshes/" + name);
  options.on_frame = [&](const FrameStats& s) { out.stats.push_back(s); };
  options.on_surface = [&](int, const MaterialSurface& s) { out.surfaces.push_back(s); };
  const Scenario scenario = parse_scenario(scenario_json, name + ".json");
  out.frame = scenario.cloth.frame;
  const RunResult result = run_scenario(scenario, options);
  EXPECT_TRUE(result.ok) << result.failure;
  return out;
}

std::filesystem::path frame_file(const Recorded& r, int frame, const char* extension) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.%s", frame, extension);
  return r.dir / name;
}

/// Connected pieces of the faces, joined through shared vertex ids only.
int pieces(const std::vector<std::vector<int>>& faces, std::size_t vertices) {
  std::vector<int> parent(vertices);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const std::vector<int>& f : faces) {
    for (int v : f) parent[root(v)] = root(f.front());
  }
  std::map<int, int> roots;
  for (const std::vector<int>& f : faces) roots[root(f.front())] = 1;
  return static_cast<int>(roots.size());
}

/// The edges of the faces that only one face has.
int boundary_edges(const std::vector<std::vector<int>>& faces) {
  std::map<std::pair<int, int>, int> faces_at_edge;
  for (const std::vector<int>& f : faces) {
    for (std::size_t k = 0; k < f.size(); ++k) {
      const int a = f[k], b = f[(k + 1) % f.size()];
      ++faces_at_edge[{std::min(a, b), std::max(a, b)}];
    }
  }
  return static_cast<int>(std::count_if(faces_at_edge.begin(), faces_at_edge.end(),
                                        [](const auto& edge) { return edge.second == 1; }));
}

/// The OBJ of every frame holds the model's particles to the last bit, its faces and its rest
/// coordinates, and as many particles, pieces and boundary edges as stats.csv says.
void expect_obj_frames_are_the_model(const Recorded& r) {
  ASSERT_EQ(r.surfaces.size(), r.stats.size());
  for (std::size_t f = 0; f < r.surfaces.size(); ++f) {
    const MaterialSurface& model = r.surfaces[f];
    const ObjPolygons obj = read_obj(frame_file(r, static_cast<int>(f), "obj"));
    ASSERT_EQ(obj.positions.size(), static_cast<std::size_t>(r.stats[f].particles)) << f;
    EXPECT_EQ(obj.positions, model.current.vertices) << "frame " << f;
    EXPECT_EQ(obj.faces, model.current.faces) << "frame " << f;
    EXPECT_EQ(static_cast<int>(obj.faces.size()), r.stats[f].faces) << "frame " << f;
    EXPECT_EQ(pieces(obj.faces, obj.positions.size()), r.stats[f].pieces) << "frame " << f;
    EXPECT_EQ(boundary_edges(obj.faces), r.stats[f].boundary_edges) << "frame " << f;
    EXPECT_EQ(obj.texture_coordinates, rest_texture_coordinates(model.rest_m, r.frame));
    EXPECT_EQ(obj.face_texture_coordinates, obj.faces) << "frame " << f;
  }
}

void expect_ply_frames_are_the_model(const Recorded& r) {
  ASSERT_EQ(r.surfaces.size(), r.stats.size());
  for (std::size_t f = 0; f < r.surfaces.size(); ++f) {
    const MaterialSurface& model = r.surfaces[f];
    const test::WrittenPly ply = test::read_written_ply(frame_file(r, static_cast<int>(f), "ply"));
    const std::vector<double>& x = ply.vertex_values.at("x");
    ASSERT_EQ(x.size(), static_cast<std::size_t>(r.stats[f].particles)) << f;
    for (std::size_t v = 0; v < x.size(); ++v) {
      const auto at = [&](const char* name) { return ply.vertex_values.at(name)[v]; };
      ASSERT_EQ(Eigen::Vector3d(at("x"), at("y"), at("z")), model.current.vertices[v])
          << "frame " << f << " vertex " << v;
      ASSERT_EQ(Eigen::Vector3d(at("rest_x"), at("rest_y"), at("rest_z")), model.rest_m[v])
          << "frame " << f << " vertex " << v;
    }
    EXPECT_EQ(ply.faces, model.current.faces) << "frame " << f;
    EXPECT_EQ(pieces(ply.faces, x.size()), r.stats[f].pieces) << "frame " << f;
  }
}

// refined at once (edges over 6 cm are bisected), then cut across at mid-height in frame 2
const char* const kRefinedAndCut = R"(,
  "adaptive": { "max_edge_length": 0.06, "min_edge_length": 0.005, "hysteresis": 0 },
  "tearing": { "cuts": [ { "time": 0.05, "line": [[-0.1, 0, 0.2], [0.5, 0, 0.2]] } ] })";

TEST(FrameMeshes, ObjFramesAreTheModelAfterRefinementAndACut) {
  const Recorded r = run(hanging_sheet("triangles", "obj", kRefinedAndCut), "refined_cut_obj");
  ASSERT_EQ(r.stats.size(), 4u);
  EXPECT_GT(r.stats[1].particles, r.stats[0].particles);  // refined
  EXPECT_GT(r.stats[3].particles, r.stats[1].particles);  // the cut split the particles on it
  EXPECT_EQ(r.stats[3].pieces, 2);
  expect_obj_frames_are_the_model(r);
}

TEST(FrameMeshes, PlyFramesAreTheModelAfterRefinementAndACut) {
  const Recorded r = run(hanging_sheet("triangles", "ply", kRefinedAndCut), "refined_cut_ply");
  ASSERT_EQ(r.stats.size(), 4u);
  EXPECT_EQ(r.stats[3].pieces, 2);
  expect_ply_frames_are_the_model(r);
}

TEST(FrameMeshes, QuadsStayQuadsInBothFormats) {
  for (const char* format : {"obj", "ply"}) {
    const Recorded r = run(hanging_sheet("quads", format, ""), std::string("quads_") + format);
    for (const MaterialSurface& s : r.surfaces) {
      ASSERT_EQ(s.current.faces.size(), 16u);
      for (const std::vector<int>& face : s.current.faces) EXPECT_EQ(face.size(), 4u);
    }
    if (std::string(format) == "obj") {
      expect_obj_frames_are_the_model(r);
    } else {
      expect_ply_frames_are_the_model(r);
    }
  }
}

/// The UV chart of a face left (x < 0.2 m) or right of the seam of seamed_sheet_obj: affine in the
/// rest position, so splits keep every corner on its chart.
Eigen::Vector2d chart_uv(const Eigen::Vector3d& rest_m, bool right) {
  return right ? Eigen::Vector2d(2.0 * rest_m.x() + 0.1, 1.5 * rest_m.z())
               : Eigen::Vector2d(2.0 * rest_m.x(), 2.5 * rest_m.z());
}

/// An OBJ of the 0.4 m x 0.4 m sheet of hanging_sheet (4 x 4 cells in triangles, x-z plane) with
/// its own UVs on two charts, seam along x = 0.2 m (all multiples of 0.05, which std::to_string's
/// 6 decimals write exactly).
std::filesystem::path seamed_sheet_obj(const std::filesystem::path& dir) {
  std::string obj;
  for (int j = 0; j <= 4; ++j) {
    for (int i = 0; i <= 4; ++i)
      obj += "v " + std::to_string(0.1 * i) + " 0 " + std::to_string(0.1 * j) + "\n";
  }
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const int a = j * 5 + i, b = a + 1, c = a + 6, d = a + 5;
      faces.push_back({a, b, c});
      faces.push_back({a, c, d});
    }
  }
  std::string f_lines;
  int vt = 0;
  for (const std::vector<int>& face : faces) {
    const bool right = (face[0] % 5) >= 2;  // every face's corners have i >= 2 or i <= 2
    f_lines += "f";
    for (int v : face) {
      const Eigen::Vector2d uv = chart_uv({0.1 * (v % 5), 0.0, 0.1 * (v / 5)}, right);
      obj += "vt " + std::to_string(uv.x()) + " " + std::to_string(uv.y()) + "\n";
      f_lines += " " + std::to_string(v + 1) + "/" + std::to_string(++vt);
    }
    f_lines += "\n";
  }
  const std::filesystem::path file = dir / "seamed_sheet.obj";
  std::ofstream(file) << obj << f_lines;
  return file;
}

/// The sheet of hanging_sheet read from seamed_sheet_obj, refined and cut as kRefinedAndCut.
std::string seamed_sheet_scenario(const std::filesystem::path& mesh, const std::string& format) {
  return R"({
  "cloth": { "mesh": { "file": ")" +
         mesh.string() + R"(" }, "density": 0.2,
             "springs": { "structural": { "stiffness": 200, "damping": 0.1 } } },
  "pins": [ { "side": "top" } ],
  "simulation": { "frames": 3, "substeps": 5 },
  "output": { "mesh_format": ")" +
         format + R"(" })" + kRefinedAndCut + R"(
})";
}

/// Each corner's UV is its face's chart at the corner's rest position.
void expect_uvs_on_their_charts(const std::vector<std::vector<int>>& faces,
                                const std::vector<std::vector<Eigen::Vector2d>>& uvs,
                                const std::vector<Eigen::Vector3d>& rest_m, std::size_t frame) {
  ASSERT_EQ(uvs.size(), faces.size()) << "frame " << frame;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    ASSERT_EQ(uvs[f].size(), faces[f].size()) << "frame " << frame << " face " << f;
    double x = 0.0;
    for (int v : faces[f]) x += rest_m[v].x() / static_cast<double>(faces[f].size());
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      EXPECT_LT((uvs[f][k] - chart_uv(rest_m[faces[f][k]], x > 0.2)).norm(), 1e-12)
          << "frame " << frame << " face " << f << " corner " << k;
    }
  }
}

TEST(FrameMeshes, ObjFramesCarryTheInputMeshsUvsThroughRefinementAndACut) {
  const std::filesystem::path mesh = seamed_sheet_obj(test::fresh_dir_for_this_test("frame_uvs"));
  const Recorded r = run(seamed_sheet_scenario(mesh, "obj"), "uvs_obj");
  ASSERT_EQ(r.stats.size(), 4u);
  EXPECT_GT(r.stats[1].particles, r.stats[0].particles);  // refined
  EXPECT_EQ(r.stats[3].pieces, 2);                        // and cut
  for (std::size_t f = 0; f < r.surfaces.size(); ++f) {
    const MaterialSurface& model = r.surfaces[f];
    const ObjPolygons obj = read_obj(frame_file(r, static_cast<int>(f), "obj"));
    EXPECT_EQ(obj.positions, model.current.vertices) << "frame " << f;
    EXPECT_EQ(obj.faces, model.current.faces) << "frame " << f;
    std::vector<std::vector<Eigen::Vector2d>> uvs;
    for (const std::vector<int>& ids : obj.face_texture_coordinates) {
      std::vector<Eigen::Vector2d>& face = uvs.emplace_back();
      for (int t : ids) face.push_back(obj.texture_coordinates.at(t).head<2>());
    }
    expect_uvs_on_their_charts(obj.faces, uvs, model.rest_m, f);
    EXPECT_EQ(uvs, model.current.face_uvs) << "frame " << f;  // to the last bit
  }
}

TEST(FrameMeshes, PlyFramesCarryTheInputMeshsUvsThroughRefinementAndACut) {
  const std::filesystem::path mesh = seamed_sheet_obj(test::fresh_dir_for_this_test("frame_uvs"));
  const Recorded r = run(seamed_sheet_scenario(mesh, "ply"), "uvs_ply");
  ASSERT_EQ(r.stats.size(), 4u);
  EXPECT_EQ(r.stats[3].pieces, 2);
  expect_ply_frames_are_the_model(r);
  for (std::size_t f = 0; f < r.surfaces.size(); ++f) {
    const MaterialSurface& model = r.surfaces[f];
    const test::WrittenPly ply = test::read_written_ply(frame_file(r, static_cast<int>(f), "ply"));
    std::vector<std::vector<Eigen::Vector2d>> uvs;
    for (const std::vector<double>& list : ply.face_texcoords) {
      std::vector<Eigen::Vector2d>& face = uvs.emplace_back();
      for (std::size_t k = 0; k + 1 < list.size(); k += 2) face.emplace_back(list[k], list[k + 1]);
    }
    expect_uvs_on_their_charts(ply.faces, uvs, model.rest_m, f);
    EXPECT_EQ(uvs, model.current.face_uvs) << "frame " << f;
  }
}

}  // namespace
}  // namespace tissu
