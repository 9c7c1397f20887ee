#include "topology/validity.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cloth_test_support.hpp"

namespace tissu {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;

class ValidityTest : public ::testing::Test {
 protected:
  void SetUp() override {
    build_cloth_complex(make_grid_mesh(test::grid(3, 3, GridCells::quads)), 0.2,
                        test::all_springs(), lcc);
    ASSERT_TRUE(validity_problems(lcc).empty());
  }
  ClothComplex lcc;
};

TEST_F(ValidityTest, ReportsNonPositiveMassAndTheMassBalance) {
  lcc.vertex_attributes().begin()->info().mass = 0.0;
  const auto problems = validity_problems(lcc);
  EXPECT_THAT(problems, Contains(HasSubstr("non-positive mass")));
  EXPECT_THAT(problems, Contains(HasSubstr("differs from density x rest area")));
}

TEST_F(ValidityTest, ReportsUnassignedSpringSlots) {
  lcc.attributes<1>().begin()->info().bending = StoredSpring{};
  lcc.info(lcc.darts().begin()).shear = StoredSpring{};
  EXPECT_THAT(validity_problems(lcc), Contains(HasSubstr("unassigned bending spring")));
  EXPECT_THAT(validity_problems(lcc), Contains(HasSubstr("unassigned shear spring")));
}

TEST_F(ValidityTest, ReportsAnEdgeWithoutItsAttributeAndAnOrphanedOne) {
  lcc.set_attribute<1>(lcc.darts().begin(), nullptr);
  const auto problems = validity_problems(lcc);
  EXPECT_THAT(problems, Contains(HasSubstr("a dart has no edge attribute")));
  EXPECT_THAT(problems, Contains(HasSubstr("edge attributes for")));
}

TEST_F(ValidityTest, EveryEdgeHasOneAttributeSharedByItsDarts) {
  int interior = 0;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.is_free<2>(d)) continue;
    ++interior;
    EXPECT_EQ(lcc.attribute<1>(d), lcc.attribute<1>(lcc.opposite<2>(d)));
  }
  EXPECT_GT(interior, 0);
  EXPECT_TRUE(validity_problems(lcc).empty());
}

TEST_F(ValidityTest, ReportsAStaleRestArea) {
  lcc.attributes<2>().begin()->info().rest_area *= 2.0;
  EXPECT_THAT(validity_problems(lcc), Contains(HasSubstr("differs from the area of its material")));
}

TEST_F(ValidityTest, ReportsNonFinitePositions) {
  lcc.vertex_attributes().begin()->point() = Point3(std::nan(""), 0, 0);
  EXPECT_THAT(validity_problems(lcc), Contains(HasSubstr("non-finite")));
}

}  // namespace
}  // namespace tissu
