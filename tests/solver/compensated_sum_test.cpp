#include "solver/compensated_sum.hpp"

#include <gtest/gtest.h>

namespace tissu {
namespace {

// 0.1 is not a binary fraction: a running sum of ten million of them is off by 1.6e-10 relative
// (999999.99983897...), the order of the drift a large cloth's total mass showed.
TEST(CompensatedSum, AddsTenMillionTenthsToTheRoundedExactSum) {
  CompensatedSum sum;
  double plain = 0.0;
  for (int i = 0; i < 10'000'000; ++i) {
    sum.add(0.1);
    plain += 0.1;
  }
  EXPECT_GT(std::abs(plain - 1e6), 1e-5);  // what the compensation is for
  EXPECT_NEAR(sum.value(), 1e6, 1e6 * 1e-15);
}

TEST(CompensatedSum, KeepsASmallTermBesideLargeOnesThatCancel) {
  CompensatedSum sum;
  for (const double x : {1e16, 1.0, -1e16}) sum.add(x);  // plain: (1e16 + 1) - 1e16 = 0
  EXPECT_EQ(sum.value(), 1.0);
}

}  // namespace
}  // namespace tissu
