#include "topology/complex_navigation.hpp"

#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "cloth_test_support.hpp"

namespace tissu {
namespace {

class ComplexNavigationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    build_cloth_complex(test::fan_with_quad(), 0.2, test::all_springs(), lcc);
  }
  /// The particle of input vertex `source`.
  Vertex_handle vertex_of(int source) {
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      if (v->info().source_index == source) return v;
    }
    ADD_FAILURE() << "no vertex from input vertex " << source;
    return lcc.vertex_attributes().begin();
  }
  ClothComplex lcc;
};

TEST_F(ComplexNavigationTest, DartsLeavingAVertexStartThereOnePerFace) {
  // the centre of the fan has six triangles, vertex 1 two triangles and the quad
  for (const auto& [source, faces] : {std::pair{0, 6}, {1, 3}, {7, 1}}) {
    const Vertex_handle v = vertex_of(source);
    const std::vector<Dart_handle> out = darts_leaving(lcc, v);
    ASSERT_EQ(out.size(), static_cast<std::size_t>(faces)) << "vertex " << source;
    EXPECT_EQ(out.front(), v->dart());
    std::set<Face_handle> seen;
    for (Dart_handle d : out) {
      EXPECT_EQ(lcc.vertex_attribute(d), v);
      EXPECT_TRUE(seen.insert(lcc.attribute<2>(d)).second) << "two darts in one face";
    }
  }
}

TEST_F(ComplexNavigationTest, AConstComplexGivesTheSameDartsAsConstHandles) {
  const ClothComplex& view = lcc;
  for (int source : {0, 1, 7}) {
    const std::vector<Dart_handle> editable = darts_leaving(lcc, vertex_of(source));
    const std::vector<Dart_const_handle> read = darts_leaving(view, vertex_of(source));
    ASSERT_EQ(read.size(), editable.size());
    for (std::size_t k = 0; k < read.size(); ++k) EXPECT_EQ(read[k], editable[k]);
  }
}

TEST_F(ComplexNavigationTest, TheVertexAfterAnEdgeIsTheTriangleApex) {
  for (Dart_const_handle d : darts_leaving(std::as_const(lcc), vertex_of(0))) {
    const Vertex_const_handle apex = vertex_after_edge(lcc, d);
    EXPECT_EQ(apex, lcc.vertex_attribute(lcc.previous(d)));  // a triangle's third corner
    EXPECT_NE(apex, lcc.vertex_attribute(d));
    EXPECT_NE(apex, lcc.vertex_attribute(lcc.next(d)));
  }
}

TEST_F(ComplexNavigationTest, TheNearestVertexIsFoundByMaterialCoordinates) {
  // the fan lies in the x-z plane: move the particles, the answer stays the rest-space one
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    v->point() = v->point() + Vector3(0.0, 5.0, 0.0);
  }
  const Vertex_handle centre = nearest_vertex(lcc, Eigen::Vector3d(0.1, 0.0, 0.05));
  EXPECT_EQ(centre->info().source_index, 0);
  const Vertex_const_handle one = nearest_vertex(std::as_const(lcc), Eigen::Vector3d(0.9, 0, 0));
  EXPECT_EQ(one->info().source_index, 1);
}

}  // namespace
}  // namespace tissu
