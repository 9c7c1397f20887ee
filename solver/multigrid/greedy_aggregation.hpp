#pragma once
/// \file
/// Greedy aggregation of a graph's nodes, the first step of an aggregation multigrid (Vanek,
/// Mandel & Brezina 1996, "Algebraic multigrid by smoothed aggregation for second and fourth order
/// elliptic problems", section 4.1). Internal to solver/multigrid.

#include <vector>

namespace tissu {

/// aggregate[i] after greedy_aggregation(): the node's aggregate, or this for a node without
/// neighbours (a pinned particle's identity row), which no aggregate takes.
inline constexpr int no_aggregate = -1;

/// Sets aggregate[i] for the `nodes` nodes of a graph whose neighbours for_each_neighbour(i, visit)
/// lists (visit(j) once or more for each neighbour j of i, i itself never), and returns the
/// number of aggregates. A node whose neighbours are all unassigned makes an aggregate with them;
/// the rest join a neighbouring aggregate of that first pass, or make one with their unassigned
/// neighbours. Deterministic: nodes are visited in index order.
template <typename ForEachNeighbour>
int greedy_aggregation(int nodes, ForEachNeighbour for_each_neighbour,
                       std::vector<int>& aggregate) {
  constexpr int unassigned = -2;
  aggregate.assign(nodes, unassigned);
  for (int i = 0; i < nodes; ++i) {
    bool isolated = true;
    for_each_neighbour(i, [&](int) { isolated = false; });
    if (isolated) aggregate[i] = no_aggregate;
  }
  int count = 0;
  for (int i = 0; i < nodes; ++i) {
    if (aggregate[i] != unassigned) continue;
    bool free_ring = true;
    for_each_neighbour(i, [&](int j) { free_ring &= aggregate[j] == unassigned; });
    if (!free_ring) continue;
    aggregate[i] = count;
    for_each_neighbour(i, [&](int j) { aggregate[j] = count; });
    ++count;
  }
  const std::vector<int> first_pass = aggregate;
  for (int i = 0; i < nodes; ++i) {
    if (aggregate[i] != unassigned) continue;
    for_each_neighbour(i, [&](int j) {
      if (aggregate[i] == unassigned && first_pass[j] >= 0) aggregate[i] = first_pass[j];
    });
  }
  for (int i = 0; i < nodes; ++i) {
    if (aggregate[i] != unassigned) continue;
    aggregate[i] = count;
    for_each_neighbour(i, [&](int j) {
      if (aggregate[j] == unassigned) aggregate[j] = count;
    });
    ++count;
  }
  return count;
}

}  // namespace tissu
