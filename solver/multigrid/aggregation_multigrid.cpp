#include "solver/multigrid/aggregation_multigrid.hpp"

#include <Eigen/LU>
#include <algorithm>

#include "solver/parallel.hpp"

namespace tissu {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Measured on the stiff hanging sheet at 81 x 81 (docs/benchmarks.md): one sweep before and after
// the coarse level, 53 ms per frame; two, 79 ms (fewer iterations, each dearer); three, 97 ms.
constexpr int coarsest_nodes = 64;      // a level this small is solved exactly
constexpr int smoothing_sweeps = 1;     // block-Jacobi sweeps before and after the coarse level
constexpr double jacobi_damping = 0.6;  // omega of the damped block-Jacobi smoother
constexpr int unassigned = -2;
constexpr int left_out = -1;

// Node i's neighbours: the other block columns of its first scalar row.
template <typename Visit>
void for_each_neighbour(const RowMatrix& matrix, int node, Visit visit) {
  const int row = 3 * node;
  int last_block = -1;
  for (RowMatrix::InnerIterator it(matrix, row); it; ++it) {
    const int block = static_cast<int>(it.col()) / 3;
    if (block != node && block != last_block && it.value() != 0.0) visit(block);
    last_block = block;
  }
}

// Vanek et al. 1996's greedy aggregation: a node whose neighbours are all free makes an aggregate
// with them; the rest join a neighbouring aggregate, or make one with their free neighbours.
// Nodes without neighbours (pinned particles, identity rows) are left out. Returns the count.
int aggregate_nodes(const RowMatrix& matrix, std::vector<int>& aggregate) {
  const int nodes = static_cast<int>(matrix.rows() / 3);
  aggregate.assign(nodes, unassigned);
  for (int i = 0; i < nodes; ++i) {
    bool isolated = true;
    for_each_neighbour(matrix, i, [&](int) { isolated = false; });
    if (isolated) aggregate[i] = left_out;
  }
  int count = 0;
  for (int i = 0; i < nodes; ++i) {
    if (aggregate[i] != unassigned) continue;
    bool free_ring = true;
    for_each_neighbour(matrix, i, [&](int j) { free_ring &= aggregate[j] == unassigned; });
    if (!free_ring) continue;
    aggregate[i] = count;
    for_each_neighbour(matrix, i, [&](int j) { aggregate[j] = count; });
    ++count;
  }
  const std::vector<int> first_pass = aggregate;
  for (int i = 0; i < nodes; ++i) {
    if (aggregate[i] != unassigned) continue;
    for_each_neighbour(matrix, i, [&](int j) {
      if (aggregate[i] == unassigned && first_pass[j] >= 0) aggregate[i] = first_pass[j];
    });
  }
  for (int i = 0; i < nodes; ++i) {
    if (aggregate[i] != unassigned) continue;
    aggregate[i] = count;
    for_each_neighbour(matrix, i, [&](int j) {
      if (aggregate[j] == unassigned) aggregate[j] = count;
    });
    ++count;
  }
  return count;
}

// The pattern of A_c = P^T A P for the piecewise-constant prolongator P of `aggregate` (3x3
// identity blocks), and the entry of A_c that each entry of A adds to (-1: none).
void build_coarse_pattern(const RowMatrix& fine, const std::vector<int>& aggregate,
                          int coarse_nodes, RowMatrix& coarse, std::vector<int>& coarse_entry) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(fine.nonZeros()));
  for (int row = 0; row < fine.rows(); ++row) {
    const int a = aggregate[row / 3];
    if (a < 0) continue;
    for (RowMatrix::InnerIterator it(fine, row); it; ++it) {
      const int b = aggregate[it.col() / 3];
      if (b >= 0) entries.emplace_back(3 * a + row % 3, 3 * b + it.col() % 3, 0.0);
    }
  }
  coarse.resize(3 * coarse_nodes, 3 * coarse_nodes);
  coarse.setFromTriplets(entries.begin(), entries.end());
  coarse.makeCompressed();
  coarse_entry.assign(static_cast<std::size_t>(fine.nonZeros()), -1);
  const int* coarse_outer = coarse.outerIndexPtr();
  const int* coarse_inner = coarse.innerIndexPtr();
  for (int row = 0; row < fine.rows(); ++row) {
    const int a = aggregate[row / 3];
    if (a < 0) continue;
    const int coarse_row = 3 * a + row % 3;
    for (int k = fine.outerIndexPtr()[row]; k < fine.outerIndexPtr()[row + 1]; ++k) {
      const int column = fine.innerIndexPtr()[k];
      const int b = aggregate[column / 3];
      if (b < 0) continue;
      const int* begin = coarse_inner + coarse_outer[coarse_row];
      const int* end = coarse_inner + coarse_outer[coarse_row + 1];
      coarse_entry[k] =
          static_cast<int>(std::lower_bound(begin, end, 3 * b + column % 3) - coarse_inner);
    }
  }
}

// A_c = P^T A P on the pattern of build_coarse_pattern(), in A's storage order (deterministic)
void galerkin_product(const RowMatrix& fine, const std::vector<int>& coarse_entry,
                      RowMatrix& coarse) {
  double* coarse_values = coarse.valuePtr();
  std::fill(coarse_values, coarse_values + coarse.nonZeros(), 0.0);
  const double* values = fine.valuePtr();
  const auto entries = static_cast<std::size_t>(fine.nonZeros());
  for (std::size_t k = 0; k < entries; ++k) {
    if (coarse_entry[k] >= 0) coarse_values[coarse_entry[k]] += values[k];
  }
}

void invert_diagonal_blocks(const RowMatrix& matrix, Eigen::Matrix3Xd& inverse) {
  const int nodes = static_cast<int>(matrix.rows() / 3);
  inverse.resize(3, 3 * nodes);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
    for (int d = 0; d < 3; ++d) {
      for (RowMatrix::InnerIterator it(matrix, 3 * i + d); it; ++it) {
        const int column = static_cast<int>(it.col()) - 3 * i;
        if (column >= 0 && column < 3) block(d, column) = it.value();
      }
    }
    inverse.block<3, 3>(0, 3 * i) = block.inverse();
  }
}

// x += omega D^-1 (b - A x), with r = b - A x left in `residual`
void jacobi_sweep(const RowMatrix& matrix, const MultigridLevel& level, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x, Eigen::VectorXd& residual) {
  residual.noalias() = b - matrix * x;
  const int nodes = static_cast<int>(x.size() / 3);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    x.segment<3>(3 * i) += jacobi_damping * (level.diagonal_inverse.block<3, 3>(0, 3 * i) *
                                             residual.segment<3>(3 * i));
  }
}

}  // namespace

void AggregationMultigrid::set_operator(const RowMatrix& finest, std::uint64_t pattern_key) {
  m_finest = &finest;
  const bool new_pattern = m_levels.empty() || pattern_key != m_pattern_key;
  m_pattern_key = pattern_key;
  if (new_pattern) {
    m_levels.resize(1);
    for (int index = 0;; ++index) {
      const int nodes = static_cast<int>(matrix(index).rows() / 3);
      if (nodes <= coarsest_nodes) break;
      MultigridLevel& fine = m_levels[index];
      const int coarse_nodes = aggregate_nodes(matrix(index), fine.aggregate);
      if (coarse_nodes == 0 || coarse_nodes * 5 > nodes * 4) break;  // no longer coarsening
      MultigridLevel coarse;
      build_coarse_pattern(matrix(index), fine.aggregate, coarse_nodes, coarse.matrix,
                           fine.coarse_entry);
      galerkin_product(matrix(index), fine.coarse_entry, coarse.matrix);  // the next aggregation
      m_levels.push_back(std::move(coarse));                              // reads its values
    }
    m_levels.back().aggregate.clear();
  }
  for (int index = 0; index < static_cast<int>(m_levels.size()); ++index) {
    MultigridLevel& level = m_levels[index];
    if (index > 0)
      galerkin_product(matrix(index - 1), m_levels[index - 1].coarse_entry, level.matrix);
    const Eigen::Index size = matrix(index).rows();
    invert_diagonal_blocks(matrix(index), level.diagonal_inverse);
    level.solution.setZero(size);
    level.residual.setZero(size);
    level.right_side.setZero(size);
  }
  m_coarsest_matrix = matrix(static_cast<int>(m_levels.size()) - 1);
  if (new_pattern || !m_coarsest) {
    m_coarsest = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>();
    m_coarsest->analyzePattern(m_coarsest_matrix);
  }
  m_coarsest->factorize(m_coarsest_matrix);
}

void AggregationMultigrid::cycle(int index) {
  MultigridLevel& level = m_levels[index];
  if (index + 1 == static_cast<int>(m_levels.size())) {
    level.solution = m_coarsest->solve(level.right_side);
    return;
  }
  // first sweep from x = 0: x = omega D^-1 b
  const int nodes = static_cast<int>(level.right_side.size() / 3);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    level.solution.segment<3>(3 * i) =
        jacobi_damping *
        (level.diagonal_inverse.block<3, 3>(0, 3 * i) * level.right_side.segment<3>(3 * i));
  }
  for (int sweep = 1; sweep < smoothing_sweeps; ++sweep) {
    jacobi_sweep(matrix(index), level, level.right_side, level.solution, level.residual);
  }
  level.residual.noalias() = level.right_side - matrix(index) * level.solution;
  MultigridLevel& coarse = m_levels[index + 1];
  coarse.right_side.setZero();
  for (int i = 0; i < nodes; ++i) {
    const int a = level.aggregate[i];
    if (a >= 0) coarse.right_side.segment<3>(3 * a) += level.residual.segment<3>(3 * i);
  }
  cycle(index + 1);
  for (int i = 0; i < nodes; ++i) {
    const int a = level.aggregate[i];
    if (a >= 0) level.solution.segment<3>(3 * i) += coarse.solution.segment<3>(3 * a);
  }
  for (int sweep = 0; sweep < smoothing_sweeps; ++sweep) {
    jacobi_sweep(matrix(index), level, level.right_side, level.solution, level.residual);
  }
}

void AggregationMultigrid::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  m_levels[0].right_side = r;
  cycle(0);
  z = m_levels[0].solution;
}

}  // namespace tissu
