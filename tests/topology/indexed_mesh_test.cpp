#include "topology/indexed_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace tissu {
namespace {

using ::testing::HasSubstr;

/// A unit quad (0 1 2 3) in the x-z plane and a triangle (1 4 2) beside it, consistently oriented.
IndexedMesh quad_and_triangle() {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {2, 0, 0.5}};
  mesh.faces = {{0, 1, 2, 3}, {1, 4, 2}};
  return mesh;
}

/// The message validate_indexed_mesh throws for `mesh`, or "" if it passes.
std::string validation_message(const IndexedMesh& mesh) {
  try {
    validate_indexed_mesh(mesh);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

TEST(ValidateIndexedMesh, AcceptsTriangleAndQuad) {
  EXPECT_NO_THROW(validate_indexed_mesh(quad_and_triangle()));
}

TEST(ValidateIndexedMesh, AcceptsQuadGrid) {
  constexpr int n = 20;
  IndexedMesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      mesh.vertices.emplace_back(i, 0, j);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      mesh.faces.push_back({v, v + 1, v + n + 2, v + n + 1});
    }
  }
  EXPECT_NO_THROW(validate_indexed_mesh(mesh));
}

TEST(ValidateIndexedMesh, DegeneracyIsRelativeToMeshSize) {
  IndexedMesh mesh = quad_and_triangle();
  for (Eigen::Vector3d& p : mesh.vertices) {
    p *= 1e-7;
  }
  EXPECT_NO_THROW(validate_indexed_mesh(mesh));
}

TEST(ValidateIndexedMesh, RejectsMeshWithoutVertices) {
  EXPECT_THAT(validation_message(IndexedMesh{}), HasSubstr("empty mesh"));
}

TEST(ValidateIndexedMesh, RejectsMeshWithoutFaces) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.faces.clear();
  EXPECT_THAT(validation_message(mesh), HasSubstr("empty mesh: it has 5 vertices and 0 faces"));
}

TEST(ValidateIndexedMesh, RejectsNanCoordinate) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.vertices[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("vertex 2 has a non-finite coordinate (nan, 0, 1)"));
}

TEST(ValidateIndexedMesh, RejectsInfiniteCoordinate) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.vertices[4].z() = -std::numeric_limits<double>::infinity();
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("vertex 4 has a non-finite coordinate (2, 0, -inf)"));
}

TEST(ValidateIndexedMesh, RejectsFaceWithTwoVertices) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.faces.push_back({3, 2});
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("face 2 has 2 vertices, but faces must have 3 or 4 vertices"));
}

TEST(ValidateIndexedMesh, RejectsPentagon) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.faces[0] = {0, 1, 4, 2, 3};
  mesh.faces.pop_back();
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("face 0 has 5 vertices, but faces must have 3 or 4 vertices"));
}

TEST(ValidateIndexedMesh, RejectsVertexIdOutOfRange) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.faces[1] = {1, 120, 2};
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("face 1 refers to vertex 120, but the mesh has 5 vertices"));
}

TEST(ValidateIndexedMesh, RejectsNegativeVertexId) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.faces[1] = {1, -1, 2};
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("face 1 refers to vertex -1, but the mesh has 5 vertices"));
}

TEST(ValidateIndexedMesh, RejectsRepeatedVertex) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.faces[0] = {0, 1, 2, 1};
  EXPECT_THAT(validation_message(mesh), HasSubstr("face 0 repeats vertex 1 (vertices 0 1 2 1)"));
}

TEST(ValidateIndexedMesh, RejectsZeroAreaFace) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.vertices[4] = {1, 0, 0.5};  // on the segment from vertex 1 to vertex 2
  EXPECT_THAT(validation_message(mesh), HasSubstr("face 1 (vertices 1 4 2) is degenerate"));
}

TEST(ValidateIndexedMesh, RejectsNonManifoldEdge) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.vertices.emplace_back(1, 1, 0.5);
  mesh.faces.push_back({2, 5, 1});
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("non-manifold edge (1, 2) is shared by 3 faces (0, 1, 2)"));
}

TEST(ValidateIndexedMesh, RejectsInconsistentOrientation) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.faces[1] = {2, 4, 1};
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("inconsistent orientation: faces 0 and 1 both traverse edge (1, 2) in the "
                        "same direction"));
}

TEST(ValidateIndexedMesh, RejectsBowTieVertexNamingIt) {
  // two triangles that touch only at vertex 2: one particle the complex would hold twice
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  mesh.faces = {{0, 1, 2}, {2, 4, 3}};
  EXPECT_THAT(validation_message(mesh), HasSubstr("non-manifold vertex 2 at (0.5, 1, 0)"));
  // a third triangle joining the two fans through edges makes vertex 2 ordinary
  mesh.faces.push_back({1, 4, 2});
  EXPECT_EQ(validation_message(mesh), "");
}

TEST(ValidateIndexedMesh, AcceptsOpenAndClosedFansAroundEveryVertex) {
  // a closed fan (the centre of a hexagon) and open ones (its rim)
  IndexedMesh mesh;
  mesh.vertices.push_back({0, 0, 0});
  for (int k = 0; k < 6; ++k) {
    const double angle = k * M_PI / 3;
    mesh.vertices.push_back({std::cos(angle), std::sin(angle), 0});
  }
  for (int k = 0; k < 6; ++k) mesh.faces.push_back({0, 1 + k, 1 + (k + 1) % 6});
  EXPECT_EQ(validation_message(mesh), "");
  // without one triangle the centre's fan is open, still one fan
  mesh.faces.pop_back();
  EXPECT_EQ(validation_message(mesh), "");
  // without an opposite one too, the centre has two fans
  mesh.faces.erase(mesh.faces.begin() + 2);
  EXPECT_THAT(validation_message(mesh), HasSubstr("non-manifold vertex 0 at (0, 0, 0)"));
}

TEST(TriangulateQuads, CutsEachQuadAlongItsShorterDiagonalAndKeepsTriangles) {
  IndexedMesh mesh = quad_and_triangle();
  mesh.vertices[2] = {1.2, 0, 1.2};  // diagonal 1-3 now shorter than 0-2
  const IndexedMesh cut = triangulate_quads(mesh);
  EXPECT_EQ(cut.vertices, mesh.vertices);
  ASSERT_EQ(cut.faces.size(), 3u);
  EXPECT_EQ(cut.faces[0], (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(cut.faces[1], (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(cut.faces[2], (std::vector<int>{1, 4, 2}));
  EXPECT_EQ(validation_message(cut), "");  // still consistently oriented

  mesh.vertices[2] = {1, 0, 1};
  mesh.vertices[0] = {0.2, 0, 0.2};  // now 0-2 is the shorter one
  EXPECT_EQ(triangulate_quads(mesh).faces[0], (std::vector<int>{0, 1, 2}));
}

/// quad_and_triangle() with a UV per corner; the two faces give their shared vertices 1 and 2
/// different UVs (a seam).
IndexedMesh quad_and_triangle_with_uvs() {
  IndexedMesh mesh = quad_and_triangle();
  mesh.face_uvs = {{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}, {{0.6, 0}, {1, 0.25}, {0.6, 0.5}}};
  return mesh;
}

TEST(ValidateIndexedMesh, AcceptsUvsOnEveryCornerSeamIncluded) {
  EXPECT_EQ(validation_message(quad_and_triangle_with_uvs()), "");
}

TEST(ValidateIndexedMesh, RejectsUvsOnSomeFacesOnlyNamingAFaceOfEach) {
  IndexedMesh mesh = quad_and_triangle_with_uvs();
  mesh.face_uvs[0].clear();
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("face 0 has no texture coordinates, but face 1 has: give every face "
                        "texture coordinates, or none"));
  mesh = quad_and_triangle_with_uvs();
  mesh.face_uvs.pop_back();  // fewer lists than faces
  EXPECT_THAT(validation_message(mesh), HasSubstr("face 1 has no texture coordinates, but face 0"));
}

TEST(ValidateIndexedMesh, RejectsAUvCountOtherThanTheCornerCount) {
  IndexedMesh mesh = quad_and_triangle_with_uvs();
  mesh.face_uvs[1].pop_back();
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("face 1 has 3 corners but 2 texture coordinates"));
}

TEST(ValidateIndexedMesh, RejectsNonFiniteUv) {
  IndexedMesh mesh = quad_and_triangle_with_uvs();
  mesh.face_uvs[0][2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(validation_message(mesh),
              HasSubstr("face 0 has a non-finite texture coordinate (0.5, nan) at corner 2"));
}

TEST(TriangulateQuads, EachTriangleKeepsTheUvsOfItsCornersInTheQuad) {
  IndexedMesh mesh = quad_and_triangle_with_uvs();
  mesh.vertices[2] = {1.2, 0, 1.2};  // cut along 1-3
  const IndexedMesh cut = triangulate_quads(mesh);
  ASSERT_EQ(cut.face_uvs.size(), 3u);
  const auto& q = mesh.face_uvs[0];
  EXPECT_EQ(cut.face_uvs[0], (std::vector<Eigen::Vector2d>{q[0], q[1], q[3]}));
  EXPECT_EQ(cut.face_uvs[1], (std::vector<Eigen::Vector2d>{q[1], q[2], q[3]}));
  EXPECT_EQ(cut.face_uvs[2], mesh.face_uvs[1]);  // the triangle's own, not the quad's
  EXPECT_EQ(validation_message(cut), "");
  EXPECT_TRUE(triangulate_quads(quad_and_triangle()).face_uvs.empty());
}

}  // namespace
}  // namespace tissu
