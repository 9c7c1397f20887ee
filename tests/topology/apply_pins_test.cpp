#include "topology/apply_pins.hpp"

#include <gtest/gtest.h>

#include "cloth_test_support.hpp"

namespace tissu {
namespace {

class ApplyPinsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // 40 x 8 cells in the x-z plane: vertex (i, j) is source index 41 j + i
    build_cloth_complex(make_grid_mesh(test::grid(40, 8, GridCells::triangles)), 0.2,
                        test::all_springs(), lcc);
  }
  std::vector<int> pinned_sources() {
    std::vector<int> out;
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      if (v->info().pinned) out.push_back(v->info().source_index);
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  ClothComplex lcc;
  ClothFrame frame;
};

TEST_F(ApplyPinsTest, EveryFourthVertexOfTheTopSideKeepsBothEnds) {
  PinSelector top;
  top.side = Side::top;
  top.every = 4;
  EXPECT_EQ(apply_pins(lcc, {top}, frame), 11);
  std::vector<int> expected;
  for (int i = 0; i <= 40; i += 4) expected.push_back(8 * 41 + i);
  EXPECT_EQ(pinned_sources(), expected);
}

TEST_F(ApplyPinsTest, EveryThirdStillPinsTheLastVertex) {
  PinSelector left;
  left.side = Side::left;
  left.every = 3;  // j = 0, 3, 6 and the end 8
  EXPECT_EQ(apply_pins(lcc, {left}, frame), 4);
  EXPECT_EQ(pinned_sources(), (std::vector<int>{0, 3 * 41, 6 * 41, 8 * 41}));
}

TEST_F(ApplyPinsTest, CornersIndicesAndBoxesUnite) {
  PinSelector corners;
  corners.kind = PinSelector::Kind::corners;
  corners.corners = {Corner::top_left, Corner::bottom_right};
  PinSelector indices;
  indices.kind = PinSelector::Kind::indices;
  indices.indices = {5, 40};  // 40 is the bottom-right corner again
  PinSelector box;
  box.kind = PinSelector::Kind::box;
  // grid origin (0.2, -0.1, 0.3), cells of 1.5/40 x 0.9/8 m: the box holds (20, 4) only
  const Eigen::Vector3d centre(0.2 + 20 * 1.5 / 40, -0.1, 0.3 + 4 * 0.9 / 8);
  box.box = Eigen::AlignedBox3d(centre.array() - 0.01, centre.array() + 0.01);
  EXPECT_EQ(apply_pins(lcc, {corners, indices, box}, frame), 4);
  EXPECT_EQ(pinned_sources(), (std::vector<int>{5, 40, 4 * 41 + 20, 8 * 41}));
}

TEST_F(ApplyPinsTest, SelectorThatSelectsNothingOrAMissingVertexIsAnError) {
  PinSelector empty_box;
  empty_box.kind = PinSelector::Kind::box;
  empty_box.box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(50), Eigen::Vector3d::Constant(51));
  try {
    apply_pins(lcc, {PinSelector{}, empty_box}, frame);
    FAIL() << "expected PinError";
  } catch (const PinError& e) {
    EXPECT_STREQ(e.what(), "pins[1]: selects no particle");
  }
  PinSelector missing;
  missing.kind = PinSelector::Kind::indices;
  missing.indices = {369};  // the grid has 41 x 9 = 369 vertices: 0 .. 368
  EXPECT_THROW(apply_pins(lcc, {missing}, frame), PinError);
}

}  // namespace
}  // namespace tissu
