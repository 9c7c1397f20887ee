// tissu's mesh writers: every vertex in order (coincident ones too), doubles that read back to
// the same bits, faces as they are, the rest coordinates as texture coordinates, and a mesh's own
// UVs per corner.

#include "lib/mesh_io/write_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "lib/mesh_io/read_mesh.hpp"
#include "lib/mesh_io/read_obj.hpp"
#include "tests/lib/written_ply.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path test_dir() {
  return test::fresh_dir_for_this_test("write_mesh");
}

/// Two pieces of a cut sheet, a quad and a triangle, that share the positions of their cut edge
/// but not their vertices, at coordinates that need all 17 digits; rest coordinates in the x-z
/// plane moved off the grid's origin.
struct CutSheet {
  IndexedMesh mesh;
  RestCoordinates rest;
};

CutSheet cut_sheet() {
  CutSheet s;
  const double third = 1.0 / 3.0;
  s.mesh.vertices = {{0, 0, 0},
                     {third, 1e-17, 0},
                     {third, 0, third},
                     {0, -0.0, third},
                     {third, 1e-17, 0},
                     {third, 0, third},
                     {0.7, 0.1, std::acos(-1.0) / 10}};
  s.mesh.faces = {{0, 1, 2, 3}, {4, 6, 5}};
  for (const Eigen::Vector3d& p : s.mesh.vertices) {
    s.rest.rest_m.push_back(Eigen::Vector3d(p.x() + 0.1, 0.0, p.z() + 2.0 / 7.0));
  }
  return s;
}

/// The cut sheet with its own UVs at digits a float cannot hold: a seam at the quad's corner
/// (1 2) against the triangle's (4 5), equal values at the quad's corner 0 and 3 (one `vt`),
/// and a -0.
CutSheet cut_sheet_with_uvs() {
  CutSheet s = cut_sheet();
  const double third = 1.0 / 3.0;
  s.mesh.face_uvs = {{{0.1, third}, {0.7, 1e-17}, {0.7, 0.9}, {0.1, third}},
                     {{2.0 / 3.0, -0.0}, {1.0, 0.5}, {2.0 / 3.0, 0.9}}};
  return s;
}

/// The UV of each corner of the OBJ's faces, through its `vt` ids; fails on a `vt` with a w.
std::vector<std::vector<Eigen::Vector2d>> corner_uvs_of(const ObjPolygons& obj) {
  std::vector<std::vector<Eigen::Vector2d>> out;
  for (const std::vector<int>& ids : obj.face_texture_coordinates) {
    std::vector<Eigen::Vector2d>& face = out.emplace_back();
    for (int t : ids) {
      EXPECT_EQ(obj.texture_coordinates[t].z(), 0.0) << "vt " << t + 1 << " has a w";
      face.push_back(obj.texture_coordinates[t].head<2>());
    }
  }
  return out;
}

TEST(WriteMesh, ObjOfAMeshWithUvsWritesOneVtPerDistinctUvAndEachCornersOwn) {
  const CutSheet s = cut_sheet_with_uvs();
  const fs::path file = test_dir() / "uvs.obj";
  write_mesh(file, s.mesh, s.rest, MeshFormat::obj);
  const ObjPolygons back = read_obj(file);
  EXPECT_EQ(back.positions, s.mesh.vertices);
  EXPECT_EQ(back.faces, s.mesh.faces);
  EXPECT_EQ(back.texture_coordinates.size(), 6u);   // 7 corners, two of them equal
  EXPECT_EQ(corner_uvs_of(back), s.mesh.face_uvs);  // to the last bit, seam included
  EXPECT_TRUE(std::signbit(back.texture_coordinates[back.face_texture_coordinates[1][0]].y()));
  std::ifstream in(file);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_THAT(text, HasSubstr("# vt u v: the cloth mesh's own texture coordinates, per face "
                              "corner"));
  EXPECT_THAT(text, ::testing::Not(HasSubstr("rest (material) position")));
  // and without rest coordinates the same
  write_mesh(file, s.mesh, MeshFormat::obj);
  EXPECT_EQ(corner_uvs_of(read_obj(file)), s.mesh.face_uvs);
}

TEST(WriteMesh, ObjWithUvsReadsBackThroughReadMeshWithItsUvsPerCorner) {
  const CutSheet s = cut_sheet_with_uvs();
  const fs::path file = test_dir() / "uvs.obj";
  write_mesh(file, s.mesh, s.rest, MeshFormat::obj);
  const IndexedMesh back = read_mesh(file);
  ASSERT_EQ(back.faces.size(), 2u);
  EXPECT_EQ(back.vertices.size(), 5u);  // the cut's two pairs joined; the UVs stay per corner
  EXPECT_EQ(back.face_uvs, s.mesh.face_uvs);
}

TEST(WriteMesh, PlyOfAMeshWithUvsWritesThemPerCornerBesideTheRestCoordinates) {
  const CutSheet s = cut_sheet_with_uvs();
  const fs::path file = test_dir() / "uvs.ply";
  write_mesh(file, s.mesh, s.rest, MeshFormat::ply);
  const test::WrittenPly back = test::read_written_ply(file);
  EXPECT_EQ(back.vertex_properties,
            (std::vector<std::string>{"x", "y", "z", "s", "t", "rest_x", "rest_y", "rest_z"}));
  EXPECT_EQ(back.vertex_values.at("rest_x").size(), s.mesh.vertices.size());
  EXPECT_EQ(back.faces, s.mesh.faces);
  ASSERT_EQ(back.face_texcoords.size(), s.mesh.faces.size());
  for (std::size_t f = 0; f < s.mesh.faces.size(); ++f) {
    std::vector<double> expected;
    for (const Eigen::Vector2d& uv : s.mesh.face_uvs[f]) {
      expected.push_back(uv.x());
      expected.push_back(uv.y());
    }
    EXPECT_EQ(back.face_texcoords[f], expected) << "face " << f;
  }
  bool said = false;
  for (const std::string& comment : back.comments) {
    said = said || comment.find("texcoord: the cloth mesh's own texture coordinates") == 0;
  }
  EXPECT_TRUE(said);
  // without the mesh's UVs, no texcoord
  write_mesh(file, cut_sheet().mesh, s.rest, MeshFormat::ply);
  EXPECT_TRUE(test::read_written_ply(file).face_texcoords.empty());
}

TEST(WriteMesh, PlyWithUvsReadsBackThroughReadMeshWhereThereIsNoSeam) {
  // assimp keeps one UV per vertex (see read_mesh.hpp): without a seam, every corner's comes back
  CutSheet s = cut_sheet_with_uvs();
  s.mesh.face_uvs[1] = {{0.7, 1e-17}, {1.0, 0.5}, {0.7, 0.9}};  // those of the quad's corners
  const fs::path file = test_dir() / "uvs.ply";
  write_mesh(file, s.mesh, s.rest, MeshFormat::ply);
  const IndexedMesh back = read_mesh(file);
  ASSERT_EQ(back.face_uvs.size(), 2u);
  for (std::size_t f = 0; f < 2; ++f) {
    ASSERT_EQ(back.face_uvs[f].size(), s.mesh.face_uvs[f].size());
    for (std::size_t k = 0; k < back.face_uvs[f].size(); ++k) {
      EXPECT_LT((back.face_uvs[f][k] - s.mesh.face_uvs[f][k]).norm(), 1e-7)  // assimp's floats
          << "face " << f << " corner " << k;
    }
  }
}

TEST(WriteMesh, UvsNotOnePerCornerThrowNamingTheFileAndTheFace) {
  CutSheet s = cut_sheet_with_uvs();
  s.mesh.face_uvs[1].pop_back();
  for (MeshFormat format : {MeshFormat::obj, MeshFormat::ply}) {
    const fs::path file = test_dir() / (std::string("uvs.") + extension(format));
    try {
      write_mesh(file, s.mesh, s.rest, format);
      FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr(file.string() + ": cannot write mesh: face 1 has 3 "
                                                      "vertices but 2 texture coordinates"));
    }
  }
}

TEST(RestTextureCoordinates, AreTheRestCoordinatesAlongTheClothFrame) {
  const std::vector<Eigen::Vector3d> rest = {{0.5, 0.25, 2.0}, {-1.0, 3.0, 0.125}};
  // the default frame: u along x, v along z, their normal u x v along -y
  const std::vector<Eigen::Vector3d> uvw = rest_texture_coordinates(rest, ClothFrame{});
  EXPECT_EQ(uvw[0], Eigen::Vector3d(0.5, 2.0, -0.25));
  EXPECT_EQ(uvw[1], Eigen::Vector3d(-1.0, 0.125, -3.0));
}

TEST(RestTextureCoordinates, GiveBackTheRestCoordinatesForAnyFrame) {
  // v_axis not orthogonal to u_axis: the writer makes it so
  const ClothFrame frame{Eigen::Vector3d(1, 1, 0).normalized(),
                         Eigen::Vector3d(0, 1, 1).normalized()};
  const Eigen::Vector3d u = frame.u_axis, n = u.cross(frame.v_axis).normalized(), v = n.cross(u);
  const std::vector<Eigen::Vector3d> rest = {{0.3, -0.7, 1.1}, {2.0, 0.0, -5.0}};
  const std::vector<Eigen::Vector3d> uvw = rest_texture_coordinates(rest, frame);
  for (std::size_t k = 0; k < rest.size(); ++k) {
    const Eigen::Vector3d back = uvw[k].x() * u + uvw[k].y() * v + uvw[k].z() * n;
    EXPECT_LT((back - rest[k]).norm(), 1e-15) << k;
  }
}

TEST(WriteMesh, ObjKeepsEveryVertexInOrderToTheLastBitWithRestAsTextureCoordinates) {
  const CutSheet s = cut_sheet();
  const fs::path file = test_dir() / "cut.obj";
  write_mesh(file, s.mesh, s.rest, MeshFormat::obj);
  const ObjPolygons back = read_obj(file);
  ASSERT_EQ(back.positions.size(), s.mesh.vertices.size());
  for (std::size_t v = 0; v < s.mesh.vertices.size(); ++v) {
    EXPECT_EQ(back.positions[v], s.mesh.vertices[v]) << "vertex " << v;
  }
  EXPECT_TRUE(std::signbit(back.positions[3].y()));  // -0 stays -0
  EXPECT_EQ(back.faces, s.mesh.faces);
  EXPECT_EQ(back.texture_coordinates, rest_texture_coordinates(s.rest.rest_m, s.rest.frame));
  EXPECT_EQ(back.face_texture_coordinates, s.mesh.faces);  // vertex k has texture coordinate k
}

TEST(WriteMesh, PlyKeepsEveryVertexInOrderInDoublesWithRestCoordinates) {
  const CutSheet s = cut_sheet();
  const fs::path file = test_dir() / "cut.ply";
  write_mesh(file, s.mesh, s.rest, MeshFormat::ply);
  const test::WrittenPly back = test::read_written_ply(file);
  EXPECT_EQ(back.vertex_properties,
            (std::vector<std::string>{"x", "y", "z", "s", "t", "rest_x", "rest_y", "rest_z"}));
  const std::vector<Eigen::Vector3d> uvw = rest_texture_coordinates(s.rest.rest_m, s.rest.frame);
  ASSERT_EQ(back.vertex_values.at("x").size(), s.mesh.vertices.size());
  for (std::size_t v = 0; v < s.mesh.vertices.size(); ++v) {
    const auto value = [&](const char* name) { return back.vertex_values.at(name)[v]; };
    EXPECT_EQ(Eigen::Vector3d(value("x"), value("y"), value("z")), s.mesh.vertices[v]) << v;
    EXPECT_EQ(Eigen::Vector3d(value("rest_x"), value("rest_y"), value("rest_z")), s.rest.rest_m[v])
        << v;
    EXPECT_EQ(value("s"), uvw[v].x());
    EXPECT_EQ(value("t"), uvw[v].y());
  }
  EXPECT_EQ(back.faces, s.mesh.faces);
  EXPECT_FALSE(back.comments.empty());
}

TEST(WriteMesh, WithoutRestCoordinatesWritesPositionsAndFacesOnly) {
  const CutSheet s = cut_sheet();
  const fs::path dir = test_dir();
  write_mesh(dir / "cut.obj", s.mesh, MeshFormat::obj);
  const ObjPolygons obj = read_obj(dir / "cut.obj");
  EXPECT_EQ(obj.positions, s.mesh.vertices);
  EXPECT_TRUE(obj.texture_coordinates.empty());
  EXPECT_EQ(obj.faces, s.mesh.faces);
  write_mesh(dir / "cut.ply", s.mesh, MeshFormat::ply);
  const test::WrittenPly ply = test::read_written_ply(dir / "cut.ply");
  EXPECT_EQ(ply.vertex_properties, (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(ply.faces, s.mesh.faces);
}

TEST(WriteMesh, WrittenFilesReadBackThroughReadMeshJoiningTheCut) {
  // what `tissu render` does with a folder of frames
  const CutSheet s = cut_sheet();
  const fs::path dir = test_dir();
  for (MeshFormat format : {MeshFormat::obj, MeshFormat::ply}) {
    const fs::path file = dir / (std::string("cut.") + extension(format));
    write_mesh(file, s.mesh, s.rest, format);
    const IndexedMesh mesh = read_mesh(file);
    EXPECT_EQ(mesh.vertices.size(), 5u) << file;  // the cut edge's two pairs joined
    EXPECT_EQ(mesh.faces.size(), 2u) << file;
  }
}

TEST(WriteMesh, RestCoordinatesOfTheWrongCountThrowNamingTheFile) {
  CutSheet s = cut_sheet();
  s.rest.rest_m.pop_back();
  const fs::path file = test_dir() / "cut.obj";
  try {
    write_mesh(file, s.mesh, s.rest, MeshFormat::obj);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string() + ": cannot write mesh: 6 rest positions for 7"));
  }
}

TEST(WriteMesh, FaceOfTwoVerticesThrowsNamingIt) {
  IndexedMesh mesh = cut_sheet().mesh;
  mesh.faces[1] = {4, 6};
  const fs::path file = test_dir() / "cut.ply";
  try {
    write_mesh(file, mesh, MeshFormat::ply);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("face 1 has 2 vertices"));
  }
}

TEST(WriteMesh, NonFinitePositionsAreRefusedNamingTheVertexAndNothingIsWritten) {
  // whatever the integrator did, no file holds inf or NaN (OBJ readers would merge such vertices)
  for (const MeshFormat format : {MeshFormat::obj, MeshFormat::ply}) {
    const fs::path dir = test_dir();
    const fs::path file = dir / (std::string("blown_up.") + extension(format));
    CutSheet s = cut_sheet();
    s.mesh.vertices[5].y() = std::numeric_limits<double>::infinity();
    EXPECT_THAT([&] { write_mesh(file, s.mesh, s.rest, format); },
                ::testing::ThrowsMessage<std::runtime_error>(
                    HasSubstr(file.string() + ": cannot write mesh: vertex 5 has the position (")));
    s = cut_sheet();
    s.rest.rest_m[2].x() = std::nan("");
    EXPECT_THAT([&] { write_mesh(file, s.mesh, s.rest, format); },
                ::testing::ThrowsMessage<std::runtime_error>(
                    HasSubstr("vertex 2 has the rest position (")));
    s.mesh.vertices[0].z() = -std::numeric_limits<double>::infinity();
    EXPECT_THAT([&] { write_mesh(file, s.mesh, format); },
                ::testing::ThrowsMessage<std::runtime_error>(HasSubstr("which is not finite")));
    EXPECT_TRUE(fs::is_empty(dir)) << "something was written";
  }
}

}  // namespace
}  // namespace tissu
