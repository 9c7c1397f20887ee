#pragma once
/// \file
/// Sums over many items that OpenMP threads share and that give the same bits on any number of
/// threads (internal): the items are cut into chunks of a fixed size, the threads sum whole chunks
/// (each in its own order), and the chunks' sums are added in chunk order. Every reduction of the
/// minimisers' iterations goes through it, so that their steps stay bitwise identical on one and
/// two threads while no part of an iteration runs serially.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "solver/parallel.hpp"

namespace tissu {

/// Items in a chunk: as few as a parallel loop's least, so that small cloths have several chunks.
inline constexpr int sum_chunk_items = min_parallel_items;

/// The sum over the chunks [begin, end) of [0, items) of chunk_sum(begin, end), computed in
/// parallel, added in chunk order.
template <typename ChunkSum>
double chunked_sum(int items, const ChunkSum& chunk_sum) {
  const int chunks = (items + sum_chunk_items - 1) / sum_chunk_items;
  constexpr int chunks_on_stack = 512;  // up to 131,072 items without an allocation
  std::array<double, chunks_on_stack> stack_sums;
  std::vector<double> heap_sums;
  double* sums = stack_sums.data();
  if (chunks > chunks_on_stack) {
    heap_sums.resize(chunks);
    sums = heap_sums.data();
  }
#pragma omp parallel for schedule(static) if (chunks > 1)
  for (int c = 0; c < chunks; ++c) {
    sums[c] = chunk_sum(c * sum_chunk_items, std::min(items, (c + 1) * sum_chunk_items));
  }
  double total = 0.0;
  for (int c = 0; c < chunks; ++c) total += sums[c];
  return total;
}

/// u . v over 3-vectors by particle (3#P each), chunked by particle.
inline double particle_dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  return chunked_sum(static_cast<int>(u.size() / 3), [&](int begin, int end) {
    return u.segment(3 * begin, 3 * (end - begin)).dot(v.segment(3 * begin, 3 * (end - begin)));
  });
}

/// |v| of a vector of 3-vectors by particle, chunked by particle.
inline double particle_norm(const Eigen::VectorXd& v) {
  return std::sqrt(particle_dot(v, v));
}

}  // namespace tissu
