#include "solver/parallel_sum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "tests/test_thread_count.hpp"

namespace tissu {
namespace {

// terms of both signs over 16 orders of magnitude: any other order of the additions gives other
// bits
std::vector<double> scattered_terms(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> exponent(-8.0, 8.0);
  std::vector<double> terms(count);
  for (double& term : terms) term = (random() % 2 ? 1.0 : -1.0) * std::pow(10.0, exponent(random));
  return terms;
}

double sum_of_range(const std::vector<double>& terms, int begin, int end) {
  double sum = 0.0;
  for (int i = begin; i < end; ++i) sum += terms[i];
  return sum;
}

TEST(ChunkedSum, AddsTheChunksSumsInChunkOrderOnAnyThreadCount) {
  // 1,000 items: the chunks' sums on the stack; 200,000: more chunks than it holds
  for (const int count : {1000, 200'000}) {
    const std::vector<double> terms = scattered_terms(count, 3);
    double in_chunk_order = 0.0;
    for (int begin = 0; begin < count; begin += sum_chunk_items) {
      in_chunk_order += sum_of_range(terms, begin, std::min(count, begin + sum_chunk_items));
    }
    ASSERT_NE(in_chunk_order, sum_of_range(terms, 0, count)) << "the order must matter here";
    for (const int threads : {1, 2}) {
      const test::ScopedThreadCount thread_count(threads);
      const double sum =
          chunked_sum(count, [&](int begin, int end) { return sum_of_range(terms, begin, end); });
      EXPECT_EQ(sum, in_chunk_order) << count << " items on " << threads << " threads";
    }
  }
}

TEST(ChunkedSum, OfNoItemsIsZeroAndCallsNothing) {
  int calls = 0;
  EXPECT_EQ(chunked_sum(0,
                        [&](int, int) {
                          ++calls;
                          return 1.0;
                        }),
            0.0);
  EXPECT_EQ(calls, 0);
}

TEST(ParticleDot, IsTheDotProductAndItsNormTheNorm) {
  const int particles = 1000;
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  Eigen::VectorXd u(3 * particles), v(3 * particles);
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    u[i] = normal(random);
    v[i] = normal(random);
  }
  EXPECT_NEAR(particle_dot(u, v), u.dot(v), 1e-12 * u.norm() * v.norm());
  EXPECT_NEAR(particle_norm(u), u.norm(), 1e-14 * u.norm());
}

}  // namespace
}  // namespace tissu
