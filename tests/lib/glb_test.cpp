// The glTF binary writer (issue 20): the file is a valid GLB container whose accessors hold the
// cloth's vertices in order, turned to glTF's y-up, its faces as triangles, unit normals along
// the cloth's normal and the rest (u, v) as TEXCOORD_0; and a glTF reader (assimp's) reads it back.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "lib/mesh_io/read_mesh.hpp"
#include "lib/mesh_io/write_mesh.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;

/// A 2 x 1 strip in the z = 0.5 plane: one quad and two triangles, counter-clockwise seen from +z.
IndexedMesh strip() {
  IndexedMesh mesh;
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= 2; ++i) mesh.vertices.emplace_back(0.5 * i, 0.5 * j, 0.5);
  mesh.faces = {{0, 1, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  return mesh;
}

/// A GLB file's JSON chunk and binary chunk (glTF 2.0 spec, 4.4 "Binary glTF Layout").
struct Glb {
  nlohmann::json json;
  std::string bin;
};

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;
}

Glb read_glb(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(u32(bytes, 4), 2u);            // version
  EXPECT_EQ(u32(bytes, 8), bytes.size());  // total length
  const std::uint32_t json_length = u32(bytes, 12);
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
  const std::size_t bin_at = 20 + json_length;
  EXPECT_EQ(bytes.substr(bin_at + 4, 4), std::string("BIN\0", 4));
  return {nlohmann::json::parse(bytes.substr(20, json_length)),
          bytes.substr(bin_at + 8, u32(bytes, bin_at))};
}

/// The floats (or uint32 indices) of accessor `index`, tightly packed as assimp writes them.
template <class T>
std::vector<T> accessor(const Glb& glb, int index, int components) {
  const nlohmann::json& a = glb.json["accessors"][index];
  const nlohmann::json& view = glb.json["bufferViews"][a["bufferView"].get<int>()];
  const std::size_t start = view.value("byteOffset", 0) + a.value("byteOffset", 0);
  std::vector<T> values(a["count"].get<std::size_t>() * components);
  std::memcpy(values.data(), glb.bin.data() + start, values.size() * sizeof(T));
  return values;
}

TEST(WriteGlb, HoldsTheVerticesInOrderYUpWithTrianglesNormalsAndRestUvs) {
  const fs::path file = test::fresh_temp_dir("glb/strip") / "frame_00000.glb";
  const IndexedMesh mesh = strip();
  write_mesh(file, mesh, RestCoordinates{mesh.vertices, ClothFrame{}}, MeshFormat::glb);
  const Glb glb = read_glb(file);
  const nlohmann::json& primitive = glb.json["meshes"][0]["primitives"][0];
  EXPECT_EQ(primitive["mode"], 4);  // triangles
  EXPECT_TRUE(glb.json["materials"][0]["doubleSided"].get<bool>());

  const auto positions = accessor<float>(glb, primitive["attributes"]["POSITION"], 3);
  ASSERT_EQ(positions.size(), 3 * mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {  // (x, y, z) -> (x, z, -y)
    EXPECT_FLOAT_EQ(positions[3 * v], mesh.vertices[v].x());
    EXPECT_FLOAT_EQ(positions[3 * v + 1], mesh.vertices[v].z());
    EXPECT_FLOAT_EQ(positions[3 * v + 2], -mesh.vertices[v].y());
  }
  const auto normals = accessor<float>(glb, primitive["attributes"]["NORMAL"], 3);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {  // +z becomes glTF's +y
    EXPECT_NEAR(normals[3 * v], 0.0f, 1e-6);
    EXPECT_NEAR(normals[3 * v + 1], 1.0f, 1e-6);
    EXPECT_NEAR(normals[3 * v + 2], 0.0f, 1e-6);
  }
  const auto uvs = accessor<float>(glb, primitive["attributes"]["TEXCOORD_0"], 2);
  EXPECT_FLOAT_EQ(uvs[2 * 5], 1.0f);  // vertex 5 rests at x = 1, z = 0.5: the default u, v axes
  EXPECT_FLOAT_EQ(uvs[2 * 5 + 1], 0.5f);

  const auto indices = accessor<std::uint32_t>(glb, primitive["indices"], 1);
  const std::vector<std::uint32_t> expected = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
  EXPECT_EQ(indices, expected);
}

TEST(WriteGlb, AGltfReaderReadsItBack) {
  const fs::path file = test::fresh_temp_dir("glb/read_back") / "strip.glb";
  write_mesh(file, strip(), MeshFormat::glb);
  const IndexedMesh read = read_mesh(file);
  EXPECT_EQ(read.vertices.size(), strip().vertices.size());
  EXPECT_EQ(read.faces.size(), 4u);  // the quad as two triangles
}

}  // namespace
}  // namespace tissu
