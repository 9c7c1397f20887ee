// group_by_label: the compressed rows of items by label that the colourings and the multigrid's
// aggregates are read through.

#include "solver/group_by_label.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tissu {
namespace {

TEST(GroupByLabel, ListsEachGroupsItemsAscendingAndLeavesOutTheUnlabelled) {
  std::vector<int> offsets, ids;
  group_by_label({2, 0, -1, 2, 0, 1, -1, 2}, 4, offsets, ids);
  EXPECT_EQ(offsets, (std::vector<int>{0, 2, 3, 6, 6}));  // group 3 is empty
  EXPECT_EQ(ids, (std::vector<int>{1, 4, 5, 0, 3, 7}));
}

}  // namespace
}  // namespace tissu
