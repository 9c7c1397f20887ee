// The thread count a cloth is worth grows with its particles and stays within what is available.

#include "lib/thread_count.hpp"

#include <gtest/gtest.h>

namespace tissu {
namespace {

TEST(ThreadsForParticles, OneThreadPerBlockOfParticlesWithinTheAvailableThreads) {
  EXPECT_EQ(threads_for_particles(0, 2), 1);
  EXPECT_EQ(threads_for_particles(21 * 21, 2), 1);  // a small cloth: one thread
  EXPECT_EQ(threads_for_particles(41 * 41, 8), 1);
  EXPECT_EQ(threads_for_particles(2 * min_particles_per_thread - 1, 8), 1);
  EXPECT_EQ(threads_for_particles(2 * min_particles_per_thread, 8), 2);
  EXPECT_EQ(threads_for_particles(51 * 51, 2), 2);
  EXPECT_EQ(threads_for_particles(81 * 81, 2), 2);
  EXPECT_EQ(threads_for_particles(1000000, 2), 2);  // never more than the cores
  EXPECT_EQ(threads_for_particles(1000000, 1), 1);
  EXPECT_EQ(threads_for_particles(5000, 0), 1);
  EXPECT_EQ(threads_for_particles(10 * min_particles_per_thread, 4), 4);  // always at least one
}

}  // namespace
}  // namespace tissu
