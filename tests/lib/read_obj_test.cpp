// tissu's OBJ reader: the file's vertex order, every corner form, negative indices, and one
// clear error naming the file and the line for each kind of bad input.

#include "lib/mesh_io/read_obj.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "lib/mesh_io/read_mesh.hpp"
#include "tests/test_temp_dir.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

fs::path obj_file(const std::string& content) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path file = test::fresh_temp_dir(std::string("read_obj/") + info->name()) / "m.obj";
  std::ofstream(file, std::ios::binary) << content;
  return file;
}

/// The message read_obj throws for `content`, or "no error".
std::string error_of(const std::string& content) {
  try {
    read_obj(obj_file(content));
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}

const char* const kSquare = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\n";

TEST(ReadObj, KeepsTheFileVertexOrderWhateverOrderTheFacesUseThem) {
  const ObjPolygons obj =
      read_obj(obj_file(std::string(kSquare) + "v 2 0 0.5\nf 5 3 2\nf 4 3 2 1\n"));
  ASSERT_EQ(obj.positions.size(), 5u);
  EXPECT_EQ(obj.positions[0], Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(obj.positions[4], Eigen::Vector3d(2, 0, 0.5));
  ASSERT_EQ(obj.faces.size(), 2u);
  EXPECT_THAT(obj.faces[0], ElementsAre(4, 2, 1));
  EXPECT_THAT(obj.faces[1], ElementsAre(3, 2, 1, 0));
  EXPECT_THAT(obj.face_lines, ElementsAre(6, 7));
}

TEST(ReadObj, ReadsEveryCornerFormAndTextureCoordinates) {
  const ObjPolygons obj = read_obj(obj_file(std::string(kSquare) +
                                            "vt 0 0\nvt 1 0 0.25\nvt 0.5\nvn 0 -1 0\n"
                                            "f 1/1/1 2/2/1 3/3/1\nf 1//1 3//1 4//1\nf 1/3 3/2 4/1\n"
                                            "f 2 3 4\n"));
  ASSERT_EQ(obj.faces.size(), 4u);
  EXPECT_THAT(obj.faces[1], ElementsAre(0, 2, 3));
  EXPECT_THAT(obj.face_texture_coordinates[0], ElementsAre(0, 1, 2));
  EXPECT_TRUE(obj.face_texture_coordinates[1].empty());
  EXPECT_THAT(obj.face_texture_coordinates[2], ElementsAre(2, 1, 0));
  EXPECT_TRUE(obj.face_texture_coordinates[3].empty());
  ASSERT_EQ(obj.texture_coordinates.size(), 3u);
  EXPECT_EQ(obj.texture_coordinates[1], Eigen::Vector3d(1, 0, 0.25));
  EXPECT_EQ(obj.texture_coordinates[2], Eigen::Vector3d(0.5, 0, 0));
}

TEST(ReadObj, NegativeIndicesCountBackFromTheLastElementDefinedBeforeTheFace) {
  const ObjPolygons obj =
      read_obj(obj_file("v 0 0 0\nv 1 0 0\nv 1 0 1\nvt 0 0\nvt 1 1\n"
                        "f -3/-2 -2/-1 -1/-1\nv 0 0 1\nf -4 -2 -1\n"));
  ASSERT_EQ(obj.faces.size(), 2u);
  EXPECT_THAT(obj.faces[0], ElementsAre(0, 1, 2));
  EXPECT_THAT(obj.face_texture_coordinates[0], ElementsAre(0, 1, 1));
  EXPECT_THAT(obj.faces[1], ElementsAre(0, 2, 3));
}

// ny, vl and e are ARCSim's own statements
TEST(ReadObj, ReadsContinuedLinesCommentsCrLfAndSkipsOtherStatements) {
  const ObjPolygons obj = read_obj(obj_file(
      "# a square\r\nmtllib m.mtl\r\no square\r\ng left\r\nv 0 0 0 # origin\r\nv 1 0 0\r\n"
      "v 1 0 \\\r\n 1\r\nv 0 0 1 1.0\r\nusemtl cloth\r\ns off\r\nf 1 2 \\\n3\r\nl 1 4\r\np 4\r\n"
      "f 1 3 4\r\nny 0 0 0\r\nvl 3\r\ne 1 2\r\n"));
  ASSERT_EQ(obj.positions.size(), 4u);
  EXPECT_EQ(obj.positions[2], Eigen::Vector3d(1, 0, 1));
  ASSERT_EQ(obj.faces.size(), 2u);
  EXPECT_THAT(obj.faces[0], ElementsAre(0, 1, 2));
  EXPECT_THAT(obj.face_lines, ElementsAre(12, 16));
}

TEST(ReadObj, ReadsNumbersToTheLastBit) {
  const ObjPolygons obj =
      read_obj(obj_file("v 0.1 -1.2345678901234567e-300 +3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_EQ(obj.positions[0], Eigen::Vector3d(0.1, -1.2345678901234567e-300, 3.0));
}

TEST(ReadObj, BadInputIsOneErrorNamingTheFileAndTheLine) {
  const std::string square = kSquare;  // lines 1 to 4
  const std::vector<std::pair<std::string, std::string>> cases = {
      {square + "\x01\x02 binary\n",
       "line 5: expected an OBJ statement (v, vt, f, ...), got \"??\""},
      {square + "1 2 3\n", "line 5: expected an OBJ statement (v, vt, f, ...), got \"1\""},
      {square + "v 1 0\n", "line 5: expected the z coordinate of a vertex, got nothing"},
      {square + "v 1 x 0\n", "line 5: expected the y coordinate of a vertex, got \"x\""},
      {square + "v 1 1e400 0\n",
       "line 5: the y coordinate of a vertex \"1e400\" is out of the range of a double"},
      {square + "v inf 0 0\n", "line 5: the vertex has a non-finite coordinate (inf, 0, 0)"},
      {square + "vt\n", "line 5: expected the u of a texture coordinate, got nothing"},
      {square + "f 1 2\n", "line 5: a face needs at least 3 corners, got 2"},
      {square + "f 1 2 0\n", "line 5: expected a face corner v, v/vt, v//vn or v/vt/vn"},
      {square + "f 1 2 3/1/1/1\n", "got \"3/1/1/1\""},
      {square + "f 1 2 a\n", "got \"a\""},
      {square + "f 1 2 /1\n", "got \"/1\""},
      {square + "\nf 1 2 9\n", "line 6: vertex index 9 is out of range: the file has 4 vertices"},
      {square + "f 1 2 -5\n",
       "line 5: vertex index -5 is out of range: only 4 are defined before this line"},
      {square + "vt 0 0\nf 1/1 2/1 3\n",
       "line 6: the face gives texture coordinates at some corners and not at others"},
      {square + "vt 0 0\nf 1/2 2/1 3/1\n",
       "line 6: texture coordinate index 2 is out of range: the file has 1 texture coordinates"},
      {square + "f 1//1 2//1 3//1\n", "line 5: normal index 1 is out of range"},
      {square + "f 1 2 99999999999999999999\n", "got \"99999999999999999999\""},
  };
  for (const auto& [content, message] : cases) {
    const std::string error = error_of(content);
    EXPECT_THAT(error, HasSubstr("m.obj: " + message.substr(0, message.find(':') + 1))) << content;
    EXPECT_THAT(error, HasSubstr(message)) << content;
  }
}

TEST(ReadNumberedMesh, ObjMapsEveryFileVertexToTheJoinedMeshVertex) {
  // vertex 4 (0-based) repeats vertex 1's position; vertex 5 is used by no face
  const NumberedMesh read =
      read_numbered_mesh(obj_file(std::string(kSquare) + "v 1 0 0\nv 7 7 7\nf 4 1 2\nf 3 4 5\n"));
  EXPECT_TRUE(read.has_vertex_numbering());
  ASSERT_EQ(read.mesh.vertices.size(), 4u);
  ASSERT_EQ(read.mesh_vertex_of_file_vertex.size(), 6u);
  for (int v : {0, 1, 2, 3}) {
    const int id = read.mesh_vertex_of_file_vertex[v];
    ASSERT_GE(id, 0);
    EXPECT_EQ(read.mesh.vertices[id], Eigen::Vector3d(v == 1 || v == 2, 0, v == 2 || v == 3));
  }
  EXPECT_EQ(read.mesh_vertex_of_file_vertex[4], read.mesh_vertex_of_file_vertex[1]);
  EXPECT_EQ(read.mesh_vertex_of_file_vertex[5], -1);
}

}  // namespace
}  // namespace tissu
