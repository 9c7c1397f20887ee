#include "lib/render/cloth_geometry.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "lib/render/vertex_normals.hpp"
#include "render_test_support.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

TEST(VertexNormals, AreTheFaceNormalOnAFlatCounterClockwiseSquare) {
  const IndexedMesh mesh = test::square_mesh(1.0, 3, false);
  for (const Eigen::Vector3f& n : vertex_normals(mesh))
    EXPECT_TRUE(n.isApprox(Eigen::Vector3f(0, 0, 1), 1e-6f)) << n.transpose();
}

TEST(VertexNormals, WeighFacesByArea) {
  // a big face in the xy plane and a small one in the xz plane meet at the edge (0,0,0)-(1,0,0)
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 3, 0}, {0, 0, 1}};
  mesh.faces = {{0, 1, 2}, {0, 3, 1}};
  const Eigen::Vector3f n = vertex_normals(mesh)[0];
  // areas 1.5 (normal +z) and 0.5 (normal +y)
  EXPECT_TRUE(n.isApprox(Eigen::Vector3f(0, 0.5f, 1.5f).normalized(), 1e-6f)) << n.transpose();
}

TEST(FaceVectorArea, IsTheAreaAlongTheNormalForAQuad) {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}};
  EXPECT_TRUE(face_vector_area(mesh, {0, 1, 2, 3}).isApprox(Eigen::Vector3d(0, 0, 6)));
}

TEST(ClothGeometry, FansQuadsIntoTrianglesButKeepsTheirFourEdges) {
  const IndexedMesh mesh = test::square_mesh(1.0, 2, true);  // 4 quads, 12 distinct edges
  RenderScene scene;
  scene.mesh = &mesh;
  scene.pinned.assign(mesh.vertices.size(), 0);
  scene.pinned[0] = scene.pinned[2] = 1;
  scene.face_strain = {0.0f, 0.1f, 0.2f, 0.3f};
  const ClothGeometry g = cloth_geometry(scene);
  EXPECT_EQ(g.triangles.size(), 4u * 2 * 3 * cloth_vertex_floats);
  EXPECT_EQ(g.edges.size(), 12u * 2 * 3);
  EXPECT_EQ(g.pins.size(), 2u * 3);
  EXPECT_FLOAT_EQ(g.triangles[cloth_vertex_floats * 6 + 6], 0.1f);  // first corner of face 1
  EXPECT_TRUE(g.bounds.min().isApprox(Eigen::Vector3d(-0.5, -0.5, 0)));
  EXPECT_TRUE(g.bounds.max().isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
}

TEST(ClothGeometry, RejectsBadScenes) {
  const IndexedMesh mesh = test::square_mesh(1.0, 1, true);
  RenderScene scene;
  EXPECT_THROW(cloth_geometry(scene), std::invalid_argument);
  scene.mesh = &mesh;
  scene.pinned = {1, 0};
  try {
    cloth_geometry(scene);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("2 pin flags for 4 vertices"));
  }
  IndexedMesh broken = mesh;
  broken.faces[0][2] = 9;
  scene = test::scene_of(broken);
  EXPECT_THROW(cloth_geometry(scene), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
