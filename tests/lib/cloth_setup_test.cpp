// Building a scenario's cloth from a mesh file: pins by index name the file's own vertices, in
// every format that numbers them, and are refused for the ones that do not.

#include "lib/cloth_setup.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "tests/test_temp_dir.hpp"
#include "topology/eigen_conversions.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

/// A 0.3 m x 0.2 m sheet of 3 x 2 cells cut into triangles, in the x-z plane, as a file stores
/// it: vertex 0 is a point no face uses, grid vertex (i, j) is file vertex 1 + 4 j + i, and the
/// faces are listed from the top row down, so that the order in which faces first use the
/// vertices is not the file's order.
struct SheetFile {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;  ///< 0-based file vertex ids, counter-clockwise
};

SheetFile sheet() {
  SheetFile s;
  s.vertices.emplace_back(5.0, 5.0, 5.0);
  for (int j = 0; j <= 2; ++j) {
    for (int i = 0; i <= 3; ++i) s.vertices.emplace_back(0.1 * i, 0.0, 0.1 * j);
  }
  const auto id = [](int i, int j) { return 1 + 4 * j + i; };
  for (int j = 1; j >= 0; --j) {
    for (int i = 0; i < 3; ++i) {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return s;
}

fs::path write_file(const fs::path& file, const std::string& content) {
  std::ofstream(file, std::ios::binary) << content;
  return file;
}

std::string obj_of(const SheetFile& s) {
  std::string out = "# a sheet\no sheet\n";
  for (const Eigen::Vector3d& p : s.vertices) {
    out += "v " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
           std::to_string(p.z()) + "\n";
  }
  for (const auto& f : s.faces) {
    out += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
           std::to_string(f[2] + 1) + "\n";
  }
  return out;
}

std::string vertex_lines(const SheetFile& s) {
  std::string out;
  for (const Eigen::Vector3d& p : s.vertices) {
    out += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
  }
  return out;
}

std::string face_lines(const SheetFile& s) {
  std::string out;
  for (const auto& f : s.faces) {
    out += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
           "\n";
  }
  return out;
}

std::string ply_of(const SheetFile& s) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(s.vertices.size()) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(s.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n" +
         vertex_lines(s) + face_lines(s);
}

std::string off_of(const SheetFile& s) {
  return "OFF\n" + std::to_string(s.vertices.size()) + " " + std::to_string(s.faces.size()) +
         " 0\n" + vertex_lines(s) + face_lines(s);
}

std::string stl_of(const SheetFile& s) {
  std::string out = "solid sheet\n";
  for (const auto& f : s.faces) {
    out += "facet normal 0 -1 0\nouter loop\n";
    for (int v : f) {
      const Eigen::Vector3d& p = s.vertices[v];
      out += "vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
             std::to_string(p.z()) + "\n";
    }
    out += "endloop\nendfacet\n";
  }
  return out + "endsolid sheet\n";
}

/// The glTF buffer: float positions, then unsigned short indices, padded to 4 bytes.
std::string gltf_buffer(const SheetFile& s) {
  std::string bytes;
  const auto append = [&](const void* data, std::size_t size) {
    bytes.append(static_cast<const char*>(data), size);
  };
  for (const Eigen::Vector3d& p : s.vertices) {
    const float xyz[3] = {static_cast<float>(p.x()), static_cast<float>(p.y()),
                          static_cast<float>(p.z())};
    append(xyz, sizeof xyz);
  }
  for (const auto& f : s.faces) {
    for (int v : f) {
      const auto index = static_cast<std::uint16_t>(v);
      append(&index, sizeof index);
    }
  }
  while (bytes.size() % 4 != 0) bytes += '\0';
  return bytes;
}

/// The glTF JSON for gltf_buffer; `uri` empty for a GLB's own buffer.
std::string gltf_json(const SheetFile& s, std::size_t buffer_bytes, const std::string& uri) {
  const std::size_t position_bytes = 12 * s.vertices.size();
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": )" +
         std::to_string(buffer_bytes) + (uri.empty() ? "" : R"(, "uri": ")" + uri + "\"") +
         R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" +
         std::to_string(position_bytes) + R"(},
                  {"buffer": 0, "byteOffset": )" +
         std::to_string(position_bytes) + R"(, "byteLength": )" +
         std::to_string(6 * s.faces.size()) + R"(}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": )" +
         std::to_string(s.vertices.size()) +
         R"(, "type": "VEC3", "min": [0, 0, 0], "max": [5, 5, 5]},
    {"bufferView": 1, "componentType": 5123, "count": )" +
         std::to_string(3 * s.faces.size()) + R"(, "type": "SCALAR"}]})";
}

std::string base64(const std::string& bytes) {
  static const char* const digits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    std::uint32_t group = static_cast<unsigned char>(bytes[k]) << 16;
    if (k + 1 < bytes.size()) group |= static_cast<unsigned char>(bytes[k + 1]) << 8;
    if (k + 2 < bytes.size()) group |= static_cast<unsigned char>(bytes[k + 2]);
    out += digits[(group >> 18) & 63];
    out += digits[(group >> 12) & 63];
    out += k + 1 < bytes.size() ? digits[(group >> 6) & 63] : '=';
    out += k + 2 < bytes.size() ? digits[group & 63] : '=';
  }
  return out;
}

std::string gltf_of(const SheetFile& s) {
  const std::string buffer = gltf_buffer(s);
  return gltf_json(s, buffer.size(), "data:application/octet-stream;base64," + base64(buffer));
}

std::string glb_of(const SheetFile& s) {
  const std::string buffer = gltf_buffer(s);
  std::string json = gltf_json(s, buffer.size(), "");
  while (json.size() % 4 != 0) json += ' ';
  std::string out;
  const auto append_u32 = [&](std::uint32_t value) {
    for (int k = 0; k < 4; ++k) out += static_cast<char>((value >> (8 * k)) & 0xff);
  };
  append_u32(0x46546C67);  // "glTF"
  append_u32(2);
  append_u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + buffer.size()));
  append_u32(static_cast<std::uint32_t>(json.size()));
  append_u32(0x4E4F534A);  // "JSON"
  out += json;
  append_u32(static_cast<std::uint32_t>(buffer.size()));
  append_u32(0x004E4942);  // "BIN"
  out += buffer;
  return out;
}

/// A scenario of the cloth in `mesh_file` with `pins`.
Scenario scenario_of(const fs::path& mesh_file, const std::string& pins) {
  const std::string text = R"({
  "cloth": { "mesh": { "file": ")" +
                           mesh_file.string() +
                           R"(" }, "density": 0.2,
             "springs": { "structural": { "stiffness": 100 } } },
  "pins": )" + pins + R"(,
  "simulation": { "frames": 1 }
})";
  return parse_scenario(text, mesh_file.parent_path() / "scenario.json");
}

/// Rest positions of the pinned particles, sorted.
std::vector<std::array<double, 3>> pinned_rest_positions(const Scenario& scenario) {
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc);
  std::vector<std::array<double, 3>> out;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (!v->info().pinned) continue;
    const Eigen::Vector3d r = to_eigen(v->info().rest_position);
    // to float precision, as glTF stores it
    out.push_back({std::round(r.x() * 1e6) / 1e6, std::round(r.y() * 1e6) / 1e6,
                   std::round(r.z() * 1e6) / 1e6});
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string pin_error(const Scenario& scenario) {
  try {
    pinned_rest_positions(scenario);
  } catch (const PinError& e) {
    return e.what();
  }
  return "no error";
}

struct Format {
  const char* extension;
  std::string (*contents)(const SheetFile&);
};

TEST(ClothSetup, PinsByIndexNameTheFileVerticesInEveryFormatThatNumbersThem) {
  const fs::path dir = test::fresh_temp_dir("cloth_setup/pins_by_index");
  // the top corners and the bottom-left one of the sheet
  const std::vector<std::array<double, 3>> expected = {
      {0.0, 0.0, 0.0}, {0.0, 0.0, 0.2}, {0.3, 0.0, 0.2}};
  const std::vector<Format> formats = {
      {"obj", obj_of}, {"ply", ply_of}, {"off", off_of}, {"gltf", gltf_of}, {"glb", glb_of}};
  for (const Format& format : formats) {
    const fs::path file =
        write_file(dir / (std::string("sheet.") + format.extension), format.contents(sheet()));
    EXPECT_EQ(pinned_rest_positions(scenario_of(file, R"([{ "indices": [9, 12, 1] }])")), expected)
        << format.extension;
  }
}

TEST(ClothSetup, PinsByIndexOnStlAreRefusedNamingTheKeyAndTheFile) {
  const fs::path dir = test::fresh_temp_dir("cloth_setup/stl");
  const fs::path file = write_file(dir / "sheet.stl", stl_of(sheet()));
  const Scenario s = scenario_of(file, R"([{ "side": "top" }, { "indices": [9, 12] }])");
  EXPECT_THAT(pin_error(s), AllOf(HasSubstr((dir / "scenario.json").string() + ": pins[1].indices"),
                                  HasSubstr(file.string()), HasSubstr("STL")));
  // other selectors work on STL
  EXPECT_EQ(pinned_rest_positions(scenario_of(file, R"([{ "side": "top" }])")).size(), 4u);
}

TEST(ClothSetup, PinsByIndexOutsideTheFileOrOnAnUnusedVertexAreRefused) {
  const fs::path dir = test::fresh_temp_dir("cloth_setup/bad_index");
  const fs::path file = write_file(dir / "sheet.obj", obj_of(sheet()));
  EXPECT_THAT(pin_error(scenario_of(file, R"([{ "indices": [13] }])")),
              AllOf(HasSubstr("pins[0].indices: vertex 13 is not a vertex of " + file.string()),
                    HasSubstr("0 to 12")));
  EXPECT_THAT(pin_error(scenario_of(file, R"([{ "indices": [3, 0] }])")),
              AllOf(HasSubstr("pins[0].indices: vertex 0 of " + file.string()),
                    HasSubstr("used by no face")));
}

TEST(ClothSetup, PinsByIndexOnAGridUseGridVertexIds) {
  const std::string text = R"({
  "cloth": { "grid": { "size": [0.3, 0.2], "resolution": [3, 2] }, "density": 0.2,
             "springs": { "structural": { "stiffness": 100 } } },
  "pins": [{ "indices": [8, 11] }],
  "simulation": { "frames": 1 }
})";
  const std::vector<std::array<double, 3>> expected = {{0.0, 0.0, 0.2}, {0.3, 0.0, 0.2}};
  EXPECT_EQ(pinned_rest_positions(parse_scenario(text, "grid.json")), expected);
}

/// A grid cloth of cells_u x cells_v quads.
Scenario quad_grid(int cells_u, int cells_v) {
  const std::string text = R"({
  "cloth": { "grid": { "size": [1, 1], "cells": "quads", "resolution": [)" +
                           std::to_string(cells_u) + ", " + std::to_string(cells_v) + R"(] },
             "density": 0.2, "springs": { "structural": { "stiffness": 100 } } },
  "simulation": { "frames": 1 }
})";
  return parse_scenario(text, "grid.json");
}

std::vector<std::string> setup_stages(const Scenario& scenario) {
  std::vector<std::string> stages;
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc, [&](const std::string& stage) { stages.push_back(stage); });
  return stages;
}

TEST(ClothSetup, ReportsBuildingALargeClothAndNotASmallOne) {
  EXPECT_THAT(setup_stages(quad_grid(320, 320)),  // 102,400 faces
              ::testing::ElementsAre("building the cloth complex: 102400 faces, 103041 particles"));
  EXPECT_THAT(setup_stages(quad_grid(316, 316)), ::testing::IsEmpty());  // 99,856 faces
}

// A strip of 2 x 500,001 vertices and 1,000,000 triangles: one vertex more than the limit.
TEST(ClothSetup, RefusesAMeshOfMoreVerticesThanACloth) {
  const fs::path dir = test::fresh_temp_dir("cloth_setup/too_large");
  const int columns = 500'001;
  std::string obj;
  obj.reserve(std::size_t{40} * 4 * columns);
  for (int k = 0; k < columns; ++k) {
    obj += "v " + std::to_string(k) + " 0 0\nv " + std::to_string(k) + " 0 1\n";
  }
  for (int k = 1; k < columns; ++k) {  // bottom vertex 2k - 1, top 2k (1-based)
    const std::string b0 = std::to_string(2 * k - 1), t0 = std::to_string(2 * k),
                      b1 = std::to_string(2 * k + 1), t1 = std::to_string(2 * k + 2);
    obj += "f " + b0 + " " + b1 + " " + t0 + "\nf " + t0 + " " + b1 + " " + t1 + "\n";
  }
  const fs::path file = write_file(dir / "strip.obj", obj);
  try {
    ClothComplex lcc;
    build_scenario_cloth(scenario_of(file, "[]"), lcc);
    ADD_FAILURE() << "a mesh of 1000002 vertices was accepted";
  } catch (const MeshError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("scenario.json: cloth.mesh.file: " + file.string()),
                                HasSubstr("1000002 vertices, more than the 1000000 particles")));
  }
}

}  // namespace
}  // namespace tissu
