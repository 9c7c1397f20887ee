#include "solver/pd/nested_dissection_ordering.hpp"

#include <metis.h>

#include <csignal>
#include <vector>

namespace tissu {
namespace {

constexpr idx_t metis_seed = 1;  // any fixed value: the same ordering on every run

/// METIS_NodeND through GKlib's signal trap. While it runs, GKlib takes SIGTERM (its SIGERR) and
/// SIGABRT (its SIGMEM) with signal(): a SIGTERM that arrives then ends METIS with METIS_ERROR and
/// is gone, and afterwards the program's own handlers come back with System V semantics
/// (reset on delivery, no SA_RESTART). Seen as a `tissu run` that ignored its SIGTERM about once
/// in 20 runs, when it came during the factor's reordering. So the program's dispositions are
/// saved and put back exactly, and a METIS_ERROR, which is how a trapped SIGTERM ends METIS (and
/// GKlib's own fatal errors, which it raises as SIGTERM too), is raised again for them.
int node_nested_dissection(idx_t& vertices, idx_t* offsets, idx_t* adjacency, idx_t* options,
                           idx_t* order, idx_t* new_index) {
  constexpr int trapped[] = {SIGTERM, SIGABRT};
  struct sigaction saved[2];
  for (int k = 0; k < 2; ++k) sigaction(trapped[k], nullptr, &saved[k]);
  const int status =
      METIS_NodeND(&vertices, offsets, adjacency, nullptr, options, order, new_index);
  for (int k = 0; k < 2; ++k) sigaction(trapped[k], &saved[k], nullptr);
  if (status == METIS_ERROR && saved[0].sa_handler != SIG_IGN) std::raise(SIGTERM);
  return status;
}

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
    if (node_nested_dissection(vertices, offsets.data(), adjacency.data(), options, order.data(),
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
