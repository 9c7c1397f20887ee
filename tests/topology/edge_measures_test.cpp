#include "topology/edge_measures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cloth_test_support.hpp"
#include "topology/rest_geometry.hpp"

namespace tissu {
namespace {

/// Moves every particle to origin + factor (X - origin), X its material coordinates.
void scale_about_origin(ClothComplex& lcc, const Eigen::Vector3d& origin, double factor) {
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& rest = v->info().rest_position;
    v->point() = Point3(origin.x() + factor * (rest.x() - origin.x()),
                        origin.y() + factor * (rest.y() - origin.y()),
                        origin.z() + factor * (rest.z() - origin.z()));
  }
}

TEST(EdgeMeasures, AScaledSheetHasTheScaleMinusOneAsStrainOnEveryEdgeAndFace) {
  const GridOptions options = test::grid(4, 3, GridCells::quads);
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(options), 0.2, test::all_springs(), lcc);
  for (double factor : {1.25, 1.0, 0.8}) {
    scale_about_origin(lcc, options.origin, factor);
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
      EXPECT_NEAR(edge_engineering_strain(lcc, d), factor - 1.0, 1e-12);
      EXPECT_NEAR(edge_strain(lcc, d), std::abs(factor - 1.0), 1e-12);
    }
    const std::vector<float> faces = face_edge_strain(lcc);
    ASSERT_EQ(faces.size(), lcc.attributes<2>().size());
    for (float strain : faces) EXPECT_NEAR(strain, factor - 1.0, 1e-6);
  }
}

TEST(EdgeMeasures, TheFaceStrainIsTheMeanOfItsEdgesInCurrentMeshOrder) {
  const GridOptions options = test::grid(3, 2, GridCells::triangles);
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(options), 0.2, test::all_springs(), lcc);
  // stretch along x only: edges along x by 30 %, along z not at all, diagonals in between
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    v->point() = Point3(1.3 * p.x(), p.y(), p.z());
  }
  const std::vector<float> faces = face_edge_strain(lcc);
  std::size_t f = 0;
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    double sum = 0.0;
    for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
      sum += edge_engineering_strain(lcc, e);
    }
    ASSERT_LT(f, faces.size());
    EXPECT_EQ(faces[f++], static_cast<float>(sum / 3.0));
  }
  EXPECT_EQ(f, faces.size());
}

TEST(EdgeMeasures, TheDihedralAngleIsTheAngleBetweenTheFaceNormals) {
  // two triangles hinged on the edge (0, 2) along y: one in the z = 0 plane, one in x = 0
  IndexedMesh folded;
  folded.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  folded.faces = {{0, 1, 2}, {0, 2, 3}};
  ClothComplex lcc;
  build_cloth_complex(folded, 0.2, test::all_springs(), lcc);
  int hinges = 0;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.is_free<2>(d)) {
      EXPECT_EQ(edge_dihedral_angle(lcc, d), 0.0);
    } else {
      EXPECT_NEAR(edge_dihedral_angle(lcc, d), std::numbers::pi / 2, 1e-12);
      ++hinges;
    }
  }
  EXPECT_EQ(hinges, 2);  // both darts of the hinge

  // unfolded flat, the hinge has no angle
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (v->info().source_index == 3) v->point() = Point3(-1, 0, 0);
  }
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    EXPECT_NEAR(edge_dihedral_angle(lcc, d), 0.0, 1e-7);
  }
}

}  // namespace
}  // namespace tissu
