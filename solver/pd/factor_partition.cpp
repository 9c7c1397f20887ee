#include "solver/pd/factor_partition.hpp"

#include <algorithm>

namespace tissu {

FactorPartition partition_factor(int columns, const int* column_offsets, const int* rows) {
  FactorPartition partition;
  partition.first_below_diagonal.resize(columns);
  std::vector<int> parent(columns, -1);
  std::vector<long> subtree_entries(columns);  // entries of the subtree rooted at each column
  std::vector<int> child_count(columns, 0);
  for (int j = 0; j < columns; ++j) {
    int k = column_offsets[j];
    while (k < column_offsets[j + 1] && rows[k] <= j) ++k;
    partition.first_below_diagonal[j] = k;
    if (k < column_offsets[j + 1]) parent[j] = rows[k];
    subtree_entries[j] = column_offsets[j + 1] - k + 1;
  }
  for (int j = 0; j < columns; ++j) {  // children come before their parents
    if (parent[j] >= 0) {
      subtree_entries[parent[j]] += subtree_entries[j];
      ++child_count[parent[j]];
    }
  }
  // the top separator: from a single root, down while a column has a single child; every other
  // column is a descendant of the chain's last column, so the chain is [separator_start, #columns)
  std::vector<int> tops;  // roots of the independent subtrees below the separator
  for (int j = 0; j < columns; ++j) {
    if (parent[j] < 0) tops.push_back(j);
  }
  partition.separator_start = columns;
  while (tops.size() == 1) {
    const int top = tops.front();
    partition.separator_start = top;
    tops.clear();
    if (child_count[top] == 0) break;
    for (int j = top - 1; j >= 0 && static_cast<int>(tops.size()) < child_count[top]; --j) {
      if (parent[j] == top) tops.push_back(j);
    }
  }
  // deal the subtrees to the halves, heaviest first to the lighter half
  std::sort(tops.begin(), tops.end(), [&](int a, int b) {
    return subtree_entries[a] != subtree_entries[b] ? subtree_entries[a] > subtree_entries[b]
                                                    : a < b;
  });
  std::vector<int> half(columns, -1);
  std::array<long, 2> load{0, 0};
  for (int top : tops) {
    const int lighter = load[1] < load[0] ? 1 : 0;
    half[top] = lighter;
    load[lighter] += subtree_entries[top];
  }
  for (int j = partition.separator_start - 1; j >= 0; --j) {  // parents before children
    if (half[j] < 0) half[j] = half[parent[j]];
  }
  partition.separator_entry.assign(columns, 0);
  for (int j = 0; j < partition.separator_start; ++j) {
    partition.half_columns[half[j]].push_back(j);
    int k = partition.first_below_diagonal[j];
    while (k < column_offsets[j + 1] && rows[k] < partition.separator_start) ++k;
    partition.separator_entry[j] = k;
  }
  return partition;
}

}  // namespace tissu
