#include "solver/pd/nested_dissection_ordering.hpp"

#include <metis.h>

#include <vector>

namespace tissu {
namespace {

constexpr idx_t metis_seed = 1;  // any fixed value: the same ordering on every run

}  // namespace

void NestedDissectionOrdering::operator()(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& matrix,
    PermutationType& permutation) const {
  idx_t vertices = static_cast<idx_t>(matrix.cols());
  std::vector<idx_t> offsets(static_cast<std::size_t>(vertices) + 1, 0);  // the graph in CSR
  std::vector<idx_t> adjacency;
  adjacency.reserve(static_cast<std::size_t>(matrix.nonZeros()));
  for (idx_t column = 0; column < vertices; ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, column); it; ++it) {
      if (it.row() != column) adjacency.push_back(static_cast<idx_t>(it.row()));
    }
    offsets[column + 1] = static_cast<idx_t>(adjacency.size());
  }
  if (vertices >= 3 && !adjacency.empty()) {
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = metis_seed;
    // order[new] = old, METIS's perm; Eigen's orderings return this inverse permutation too
    std::vector<idx_t> order(vertices), new_index(vertices);
    if (METIS_NodeND(&vertices, offsets.data(), adjacency.data(), nullptr, options, order.data(),
                     new_index.data()) == METIS_OK) {
      permutation.resize(static_cast<int>(vertices));
      for (idx_t position = 0; position < vertices; ++position) {
        permutation.indices()[position] = static_cast<int>(order[position]);
      }
      return;
    }
  }
  Eigen::AMDOrdering<int>()(matrix, permutation);
}

}  // namespace tissu
