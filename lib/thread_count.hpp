#pragma once
/// \file
/// How many OpenMP threads a cloth of a given size is worth, for programs whose user chose none.

#include <algorithm>

namespace tissu {

/// Particles each thread should have at least: below, another thread costs the solver more than
/// it saves, since each parallel loop of a step wakes the sleeping threads (passive waiting) for a
/// few microseconds of work. On the hanging sheet (Newton, quasi-Newton), two threads were 2.5
/// times slower than one at 21 x 21 particles, 5 to 13 % slower at 41 x 41, 6 to 12 % faster at
/// 51 x 51 and 1.4 times faster at 81 x 81 (docs/benchmarks.md, "Threads by cloth size").
inline constexpr int min_particles_per_thread = 1250;

/// As many threads as give each min_particles_per_thread particles, at least one and at most
/// `available_threads` (the cores, or what the user allows).
inline int threads_for_particles(int particles, int available_threads) {
  return std::max(1, std::min(particles / min_particles_per_thread, available_threads));
}

}  // namespace tissu
