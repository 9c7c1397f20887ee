#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "lib/mesh_io/read_mesh.hpp"
#include "lib/mesh_io/write_mesh.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

/// A fresh directory for the running test.
fs::path test_dir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return test::fresh_temp_dir(std::string("mesh_io/") + info->name());
}

fs::path write_file(const fs::path& file, const std::string& content) {
  std::ofstream(file, std::ios::binary) << content;
  return file;
}

/// The message read_mesh throws for `file`, or "" if it reads.
std::string read_error(const fs::path& file) {
  try {
    read_mesh(file);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

/// 3 x 2 grid of unit cells in the x-z plane: four quads and two triangles (one cell split).
IndexedMesh mixed_grid() {
  IndexedMesh mesh;
  for (int j = 0; j <= 2; ++j) {
    for (int i = 0; i <= 3; ++i) {
      mesh.vertices.emplace_back(0.1 * i + 0.01 * j, 0.003 * i * j, 0.1 * j);
    }
  }
  mesh.faces = {{0, 1, 5, 4}, {1, 2, 6, 5},  {2, 3, 7},     {2, 7, 6},
                {4, 5, 9, 8}, {5, 6, 10, 9}, {6, 7, 11, 10}};
  return mesh;
}

/// Same faces, in the same order, with the same sizes and corner positions (to float precision).
void expect_same_mesh(const IndexedMesh& expected, const IndexedMesh& actual) {
  ASSERT_EQ(actual.vertices.size(), expected.vertices.size());
  ASSERT_EQ(actual.faces.size(), expected.faces.size());
  for (std::size_t f = 0; f < expected.faces.size(); ++f) {
    ASSERT_EQ(actual.faces[f].size(), expected.faces[f].size()) << "face " << f;
    for (std::size_t i = 0; i < expected.faces[f].size(); ++i) {
      const Eigen::Vector3d& p = expected.vertices[expected.faces[f][i]];
      const Eigen::Vector3d& q = actual.vertices[actual.faces[f][i]];
      EXPECT_LT((p - q).norm(), 1e-6) << "face " << f << " corner " << i;
    }
  }
}

/// Vertex ids used by both faces.
std::size_t shared_vertices(const std::vector<int>& a, const std::vector<int>& b) {
  return std::count_if(a.begin(), a.end(),
                       [&](int v) { return std::find(b.begin(), b.end(), v) != b.end(); });
}

const char* const kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";

// a unit square of two triangles at z in [0, 1], in a node translated by (0, 0, 2)
const char* const kGltf = R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0, "translation": [0, 0, 2]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAAAAAAIA/AAAAAAAAAAAAAIA/AAABAAIAAAACAAMA"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 0, 1]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";

TEST(WriteMesh, ObjRoundTripKeepsTrianglesAndQuads) {
  const fs::path file = test_dir() / "grid.obj";
  write_mesh(file, mixed_grid(), MeshFormat::obj);
  expect_same_mesh(mixed_grid(), read_mesh(file));
}

TEST(WriteMesh, ObjWritesNoMaterialFile) {
  const fs::path dir = test_dir();
  write_mesh(dir / "grid.obj", mixed_grid(), MeshFormat::obj);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(WriteMesh, PlyRoundTripKeepsTrianglesAndQuads) {
  const fs::path file = test_dir() / "grid.ply";
  write_mesh(file, mixed_grid(), MeshFormat::ply);
  expect_same_mesh(mixed_grid(), read_mesh(file));
}

TEST(WriteMesh, OverwritesAnExistingFile) {
  const fs::path file = write_file(test_dir() / "grid.ply", "old content");
  write_mesh(file, mixed_grid(), MeshFormat::ply);
  expect_same_mesh(mixed_grid(), read_mesh(file));
}

TEST(WriteMesh, UnwritableFileThrowsNamingIt) {
  const fs::path file = test_dir() / "no_such_dir" / "grid.obj";
  try {
    write_mesh(file, mixed_grid(), MeshFormat::obj);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
  }
}

TEST(WriteMesh, FaceOutOfRangeThrowsNamingFile) {
  IndexedMesh mesh = mixed_grid();
  mesh.faces[2] = {2, 3, 99};
  const fs::path file = test_dir() / "grid.ply";
  try {
    write_mesh(file, mesh, MeshFormat::ply);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr(file.string()), HasSubstr("face 2 refers to vertex 99")));
  }
}

TEST(MeshFormat, ParsesNamesAndGivesExtensions) {
  EXPECT_EQ(mesh_format_from_string("obj"), MeshFormat::obj);
  EXPECT_EQ(mesh_format_from_string("ply"), MeshFormat::ply);
  EXPECT_EQ(mesh_format_from_string("glb"), MeshFormat::glb);
  EXPECT_STREQ(extension(MeshFormat::glb), "glb");
  EXPECT_STREQ(extension(MeshFormat::obj), "obj");
  EXPECT_STREQ(extension(MeshFormat::ply), "ply");
}

TEST(MeshFormat, UnknownNameThrowsListingAcceptedOnes) {
  try {
    mesh_format_from_string("stl");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("stl"), HasSubstr("\"obj\""), HasSubstr("\"ply\"")));
  }
}

TEST(ReadMesh, ObjIsNotCutAtUvSeams) {
  // the two faces share vertices 2 and 3 but give them different texture coordinates
  const fs::path file = write_file(test_dir() / "seam.obj",
                                   "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 2 0 0.5\n"
                                   "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nvn 0 -1 0\n"
                                   "f 1/1/1 2/2/1 3/3/1 4/4/1\nf 2/5/1 5/1/1 3/2/1\n");
  const IndexedMesh mesh = read_mesh(file);
  ASSERT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.faces[0].size(), 4u);
  EXPECT_EQ(mesh.faces[1].size(), 3u);
  EXPECT_EQ(shared_vertices(mesh.faces[0], mesh.faces[1]), 2u);
}

TEST(ReadMesh, ObjKeepsItsUvsPerCornerAcrossASeam) {
  // vertices 2 and 3 (1-based) have other UVs in the triangle than in the quad
  const fs::path file = write_file(test_dir() / "seam.obj",
                                   "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 2 0 0.5\n"
                                   "vt 0 0\nvt 0.5 0\nvt 0.5 0.5 0.75\nvt 0 0.5\nvt 0.625 0\n"
                                   "vt 1 0.25\nvt 0.625 0.5\n"
                                   "f 1/1 2/2 3/3 4/4\nf 2/5 5/6 3/7\n");
  const IndexedMesh mesh = read_mesh(file);
  ASSERT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.face_uvs.size(), 2u);
  EXPECT_EQ(mesh.face_uvs[0],
            (std::vector<Eigen::Vector2d>{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}));
  EXPECT_EQ(mesh.face_uvs[1], (std::vector<Eigen::Vector2d>{{0.625, 0}, {1, 0.25}, {0.625, 0.5}}));
  EXPECT_EQ(mesh.faces[0][1], mesh.faces[1][0]);  // one vertex, two UVs
}

TEST(ReadMesh, ObjWithoutUvsHasNone) {
  const fs::path file =
      write_file(test_dir() / "plain.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nvt 0 0\nf 1 2 3\n");
  EXPECT_FALSE(read_mesh(file).has_uvs());
}

TEST(ReadMesh, UvsOnSomeFacesOnlyAreRefusedNamingAFaceOfEach) {
  const fs::path file = write_file(test_dir() / "some.obj",
                                   "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\n"
                                   "f 1 2 3\nf 1/1 3/3 4/2\n");
  EXPECT_THAT(read_error(file),
              HasSubstr(file.string() + ": face 0 has no texture coordinates, but face 1 has: "
                                        "give every face texture coordinates, or none"));
}

TEST(ReadPolygons, IgnoresUvsEvenOnSomeFacesOnly) {
  // an obstacle has no use for UVs, so it is not refused for them
  const fs::path file = write_file(test_dir() / "some.obj",
                                   "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\n"
                                   "f 1 2 3\nf 1/1 3/1 4/1\n");
  const IndexedMesh mesh = read_polygons(file);
  EXPECT_EQ(mesh.faces.size(), 2u);
  EXPECT_FALSE(mesh.has_uvs());
}

TEST(ReadMesh, PlyVertexUvsOfVerticesRepeatedAtASeamBecomePerCornerUvs) {
  // vertices 1 and 4, 2 and 5 are at the same positions with other UVs: joined, the seam stays
  const fs::path file = write_file(
      test_dir() / "seam.ply",
      "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
      "property float z\nproperty float s\nproperty float t\nelement face 2\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0\n1 0 0 0.5 0\n1 0 1 0.5 0.5\n0 0 1 0 0.5\n1 0 0 0.625 0\n1 0 1 0.625 0.5\n"
      "2 0 0.5 1 0.25\n"
      "4 0 1 2 3\n3 4 6 5\n");
  const NumberedMesh read = read_numbered_mesh(file);
  const IndexedMesh& mesh = read.mesh;
  ASSERT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.face_uvs.size(), 2u);
  EXPECT_EQ(mesh.face_uvs[0],
            (std::vector<Eigen::Vector2d>{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}));
  EXPECT_EQ(mesh.face_uvs[1], (std::vector<Eigen::Vector2d>{{0.625, 0}, {1, 0.25}, {0.625, 0.5}}));
  EXPECT_EQ(mesh.faces[0][1], mesh.faces[1][0]);
  EXPECT_EQ(read.mesh_vertex_of_file_vertex[4], read.mesh_vertex_of_file_vertex[1]);
}

TEST(ReadMesh, GltfUvsAreReadWithAssimpsFlipToVUp) {
  // kGltf's square with TEXCOORD_0 (0, 0) (0.5, 0) (0.5, 0.25) (0, 0.25), faces 0 1 2 and 0 2 3
  const std::string gltf = R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}]}],
  "buffers": [{"byteLength": 92, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAAAAAAIA/AAAAAAAAAAAAAIA/AAAAAAAAAAAAAAA/AAAAAAAAAD8AAIA+AAAAAAAAgD4AAAEAAgAAAAIAAwA="}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 0, 1]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
  const IndexedMesh mesh = read_mesh(write_file(test_dir() / "square.gltf", gltf));
  ASSERT_EQ(mesh.face_uvs.size(), 2u);
  // glTF's v runs down from the image's top; assimp gives 1 - v, OBJ's convention
  EXPECT_EQ(mesh.face_uvs[0], (std::vector<Eigen::Vector2d>{{0, 1}, {0.5, 1}, {0.5, 0.75}}));
  EXPECT_EQ(mesh.face_uvs[1], (std::vector<Eigen::Vector2d>{{0, 1}, {0.5, 0.75}, {0, 0.75}}));
}

TEST(ReadMesh, ObjObjectsAreJoinedIntoOneMesh) {
  const fs::path file = write_file(test_dir() / "objects.obj",
                                   "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\n"
                                   "o left\nf 1 2 3\no right\nf 1 3 4\n");
  const IndexedMesh mesh = read_mesh(file);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(shared_vertices(mesh.faces[0], mesh.faces[1]), 2u);
}

TEST(ReadMesh, ObjPointsAndLinesAreIgnored) {
  const fs::path file = write_file(test_dir() / "lines.obj",
                                   "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 5 5 5\nf 1 2 3\nl 1 4\np 4\n");
  const IndexedMesh mesh = read_mesh(file);
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.faces.size(), 1u);
}

TEST(ReadMesh, ObjWithOnlyLinesIsEmpty) {
  const fs::path file = write_file(test_dir() / "only_lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string()), HasSubstr("empty mesh")));
}

TEST(ReadMesh, PlyAscii) {
  const fs::path file = write_file(test_dir() / "square.ply", std::string(kPlyHeader) +
                                                                  "0 0 0\n1 0 0\n1 0 1\n0 0 1\n"
                                                                  "3 0 1 2\n3 0 2 3\n");
  const IndexedMesh mesh = read_mesh(file);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.vertices[2], Eigen::Vector3d(1, 0, 1));
}

TEST(ReadMesh, OffKeepsQuads) {
  const fs::path file = write_file(test_dir() / "mixed.off",
                                   "OFF\n5 2 0\n0 0 0\n1 0 0\n1 0 1\n0 0 1\n2 0 0.5\n"
                                   "4 0 1 2 3\n3 1 4 2\n");
  const IndexedMesh mesh = read_mesh(file);
  EXPECT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(mesh.faces[0].size(), 4u);
  EXPECT_EQ(mesh.faces[1].size(), 3u);
}

TEST(ReadMesh, StlTriangleSoupIsWelded) {
  const fs::path file = write_file(test_dir() / "square.stl",
                                   "solid square\n"
                                   "facet normal 0 -1 0\nouter loop\n"
                                   "vertex 0 0 0\nvertex 1 0 0\nvertex 1 0 1\n"
                                   "endloop\nendfacet\n"
                                   "facet normal 0 -1 0\nouter loop\n"
                                   "vertex 0 0 0\nvertex 1 0 1\nvertex 0 0 1\n"
                                   "endloop\nendfacet\n"
                                   "endsolid square\n");
  const IndexedMesh mesh = read_mesh(file);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(shared_vertices(mesh.faces[0], mesh.faces[1]), 2u);
}

TEST(ReadMesh, BinaryStlTriangleSoupIsWelded) {
  const float triangles[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}},
                                    {{0, 0, 0}, {1, 0, 1}, {0, 0, 1}}};
  std::string content(80, ' ');  // header
  const auto append = [&](const void* data, std::size_t size) {
    content.append(static_cast<const char*>(data), size);
  };
  const std::uint32_t count = 2;
  append(&count, sizeof count);
  for (const auto& triangle : triangles) {
    const float normal[3] = {0, -1, 0};
    const std::uint16_t attributes = 0;
    append(normal, sizeof normal);
    append(triangle, sizeof triangle);
    append(&attributes, sizeof attributes);
  }
  const IndexedMesh mesh = read_mesh(write_file(test_dir() / "square.stl", content));
  EXPECT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.faces.size(), 2u);
  EXPECT_EQ(shared_vertices(mesh.faces[0], mesh.faces[1]), 2u);
}

TEST(ReadMesh, GltfAppliesNodeTransform) {
  const fs::path file = write_file(test_dir() / "square.gltf", kGltf);
  const IndexedMesh mesh = read_mesh(file);
  ASSERT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.faces.size(), 2u);
  for (const Eigen::Vector3d& p : mesh.vertices) {
    EXPECT_GE(p.z(), 2.0);
    EXPECT_LE(p.z(), 3.0);
  }
}

TEST(ReadMesh, SampleMeshesAreValid) {
  const IndexedMesh patch = read_mesh(fs::path(TISSU_DATA_DIR) / "meshes" / "quad_patch.obj");
  EXPECT_EQ(patch.vertices.size(), 25u);
  EXPECT_EQ(patch.faces.size(), 16u);
  const IndexedMesh flag = read_mesh(fs::path(TISSU_DATA_DIR) / "meshes" / "flag.obj");
  EXPECT_EQ(flag.vertices.size(), 35u);
  EXPECT_EQ(flag.faces.size(), 48u);
}

TEST(ReadMesh, MissingFileIsNamed) {
  const fs::path file = test_dir() / "missing.obj";
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string()), HasSubstr("no such file")));
}

TEST(ReadMesh, DirectoryIsRejected) {
  const fs::path dir = test_dir();
  EXPECT_THAT(read_error(dir), AllOf(HasSubstr(dir.string()), HasSubstr("directory")));
}

TEST(ReadMesh, GarbageIsRejected) {
  const fs::path dir = test_dir();
  const fs::path text = write_file(dir / "garbage.obj", "this is not a mesh\n\x01\x02 at all\n");
  EXPECT_THAT(read_error(text), HasSubstr(text.string()));
  const fs::path binary =
      write_file(dir / "garbage.bin", std::string("\x7f\x01\x02\x03\x00\xff", 6));
  EXPECT_THAT(read_error(binary), AllOf(HasSubstr(binary.string()), HasSubstr("cannot read mesh")));
}

TEST(ReadMesh, ObjIndexOutOfRangeIsRejected) {
  const fs::path file =
      write_file(test_dir() / "range.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nf 1 2 3\nf 1 3 9\n");
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string()), HasSubstr("out of range")));
}

TEST(ReadMesh, PlyIndexOutOfRangeIsRejected) {
  const fs::path file = write_file(test_dir() / "range.ply", std::string(kPlyHeader) +
                                                                 "0 0 0\n1 0 0\n1 0 1\n0 0 1\n"
                                                                 "3 0 1 2\n3 0 2 9\n");
  EXPECT_THAT(read_error(file),
              AllOf(HasSubstr(file.string()),
                    HasSubstr("face 1 refers to vertex 9, but the mesh has 4 vertices")));
}

TEST(ReadMesh, PlyNegativeIndexIsRejected) {
  const fs::path file = write_file(test_dir() / "negative.ply", std::string(kPlyHeader) +
                                                                    "0 0 0\n1 0 0\n1 0 1\n0 0 1\n"
                                                                    "3 0 1 2\n3 0 2 -1\n");
  EXPECT_THAT(read_error(file),
              AllOf(HasSubstr(file.string()),
                    HasSubstr("face 1 refers to vertex -1, but the mesh has 4 vertices")));
}

TEST(ReadMesh, OffIndexOutOfRangeIsRejected) {
  // assimp's OFF loader clamps the index to the last vertex and only logs an error
  const fs::path file = write_file(test_dir() / "range.off",
                                   "OFF\n4 2 0\n0 0 0\n1 0 0\n1 0 1\n0 0 1\n3 0 1 2\n3 0 2 7\n");
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string()), HasSubstr("out of range")));
}

TEST(ReadMesh, TruncatedOffIsRejected) {
  const fs::path file =
      write_file(test_dir() / "truncated.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n1 0 1\n0 0 1\n3 0 1 2\n");
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string()), HasSubstr("cannot read mesh")));
}

TEST(ReadMesh, GltfIndexOutOfRangeIsRejected) {
  // assimp's glTF loader drops faces with out-of-range indices and only logs a warning
  std::string gltf = kGltf;
  const std::string good = "AAACAAMA";                     // indices 0 2 3 of the second triangle
  gltf.replace(gltf.find(good), good.size(), "AAACAAkA");  // indices 0 2 9
  const fs::path file = write_file(test_dir() / "range.gltf", gltf);
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string()), HasSubstr("out-of-range")));
}

TEST(ReadMesh, NonManifoldMeshIsRejected) {
  const fs::path file = write_file(test_dir() / "fan.obj",
                                   "v 0 0 0\nv 1 0 0\nv 0.5 0 1\nv 0.5 1 1\nv 0.5 -1 1\n"
                                   "f 1 2 3\nf 2 1 4\nf 2 1 5\n");
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string() + ": non-manifold edge")));
}

TEST(ReadMesh, NanCoordinateIsRejected) {
  const fs::path file =
      write_file(test_dir() / "nan.obj", "v 0 0 0\nv nan 0 0\nv 1 0 1\nf 1 2 3\n");
  EXPECT_THAT(
      read_error(file),
      HasSubstr(file.string() + ": line 2: the vertex has a non-finite coordinate (nan, 0, 0)"));
}

TEST(ReadMesh, PlyNanCoordinateIsRejected) {
  const fs::path file = write_file(test_dir() / "nan.ply", std::string(kPlyHeader) +
                                                               "0 0 0\nnan 0 0\n1 0 1\n0 0 1\n"
                                                               "3 0 1 2\n3 0 2 3\n");
  EXPECT_THAT(read_error(file), AllOf(HasSubstr(file.string()), HasSubstr("non-finite")));
}

TEST(ReadMesh, PentagonIsRejected) {
  const fs::path file =
      write_file(test_dir() / "pentagon.obj",
                 "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0.5 0 1.5\nv 0 0 1\nf 1 2 3 4 5\n");
  EXPECT_THAT(read_error(file),
              AllOf(HasSubstr(file.string()), HasSubstr("face 0 has 5 vertices")));
}

}  // namespace
}  // namespace tissu
