#include "solver/multigrid/aggregation_multigrid.hpp"

#include <Eigen/LU>
#include <algorithm>

#include "solver/group_by_label.hpp"
#include "solver/multigrid/greedy_aggregation.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

// Chosen on the stiff hanging sheet at 81 x 81 (docs/benchmarks.md, "Newton preconditioned by
// multigrid"): one sweep before and after the coarse level ran in 53 ms per frame, two in 79 ms
// (fewer iterations, each dearer), three in 97 ms (omega 0.6); omega 0.5, 0.6, 0.7, 0.8 and 0.9
// took 40.6, 32.1, 33.7, 28.1 and 31.5 V-cycles per step.
constexpr int coarsest_nodes = 64;      // a level this small is solved exactly
constexpr double jacobi_damping = 0.8;  // omega of the damped block-Jacobi smoother

// Node i's neighbours: the nodes of its nonzero off-diagonal blocks.
template <typename Visit>
void for_each_neighbour(const SymmetricBlockMatrix& matrix, int node, Visit visit) {
  for (int k = matrix.offsets[node]; k < matrix.offsets[node + 1]; ++k) {
    if (k != matrix.diagonal[node] && !matrix.block(k).isZero(0.0)) visit(matrix.columns[k]);
  }
}

// Vanek et al. 1996's greedy aggregation of the nodes coupled by nonzero off-diagonal blocks.
// Returns the count.
int aggregate_nodes(const SymmetricBlockMatrix& matrix, std::vector<int>& aggregate) {
  return greedy_aggregation(
      matrix.node_count(), [&](int node, auto visit) { for_each_neighbour(matrix, node, visit); },
      aggregate);
}

// The pattern of B, the sums B(r, c) of A's blocks (i, j) with r = row_map[i] and c =
// column_map[j] (a null map: the identity; -1: dropped), with `rows` rows, and the block of B
// each block of A adds to (-1: none). The diagonal indices are set when B is square.
void build_summed_pattern(const SymmetricBlockMatrix& a, const std::vector<int>* row_map,
                          const std::vector<int>* column_map, int rows, bool square,
                          SymmetricBlockMatrix& b, std::vector<int>& block_map) {
  const auto map_row = [&](int i) { return row_map != nullptr ? (*row_map)[i] : i; };
  const auto map_column = [&](int j) { return column_map != nullptr ? (*column_map)[j] : j; };
  std::vector<std::vector<int>> columns(rows);
  for (int i = 0; i < a.row_count(); ++i) {
    const int r = map_row(i);
    if (r < 0) continue;
    for (int k = a.offsets[i]; k < a.offsets[i + 1]; ++k) {
      const int c = map_column(a.columns[k]);
      if (c >= 0) columns[r].push_back(c);
    }
  }
  b.offsets.assign(1, 0);
  b.columns.clear();
  b.diagonal.assign(square ? rows : 0, -1);
  for (int r = 0; r < rows; ++r) {
    std::vector<int>& row = columns[r];
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    const auto diagonal = std::lower_bound(row.begin(), row.end(), r);
    if (square) b.diagonal[r] = b.offsets.back() + static_cast<int>(diagonal - row.begin());
    b.columns.insert(b.columns.end(), row.begin(), row.end());
    b.offsets.push_back(static_cast<int>(b.columns.size()));
  }
  b.values.assign(6 * b.columns.size(), 0.0);
  block_map.assign(a.columns.size(), -1);
  for (int i = 0; i < a.row_count(); ++i) {
    const int r = map_row(i);
    if (r < 0) continue;
    const auto begin = b.columns.begin() + b.offsets[r];
    const auto end = b.columns.begin() + b.offsets[r + 1];
    for (int k = a.offsets[i]; k < a.offsets[i + 1]; ++k) {
      const int c = map_column(a.columns[k]);
      if (c >= 0)
        block_map[k] = static_cast<int>(std::lower_bound(begin, end, c) - b.columns.begin());
    }
  }
}

// B's values on the pattern of build_summed_pattern(), summed in A's storage order (deterministic)
void sum_blocks(const SymmetricBlockMatrix& a, const std::vector<int>& block_map,
                SymmetricBlockMatrix& b) {
  std::fill(b.values.begin(), b.values.end(), 0.0);
  for (int k = 0; k < a.block_count(); ++k) {
    if (block_map[k] >= 0) b.block(block_map[k]) += a.block(k);
  }
}

// A P and A_c = P^T (A P) for the piecewise-constant prolongator P of fine.aggregate (3x3
// identity blocks): A P sums each row's blocks by aggregate, P^T then sums its rows.
void galerkin_product(const SymmetricBlockMatrix& a, MultigridLevel& fine,
                      SymmetricBlockMatrix& coarse) {
  sum_blocks(a, fine.prolongated_block, fine.prolongated);
  sum_blocks(fine.prolongated, fine.coarse_block, coarse);
}

// x += omega D^-1 r node by node, or x = omega D^-1 r (the sweep from x = 0) unless `accumulate`
void jacobi_sweep(const MultigridLevel& level, const Eigen::VectorXd& r, Eigen::VectorXd& x,
                  bool accumulate) {
  const int nodes = static_cast<int>(x.size() / 3);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    const Eigen::Vector3d step =
        jacobi_damping * (level.diagonal_inverse.block<3, 3>(0, 3 * i) * r.segment<3>(3 * i));
    if (accumulate) {
      x.segment<3>(3 * i) += step;
    } else {
      x.segment<3>(3 * i) = step;
    }
  }
}

// the inverse of each node's diagonal block
void invert_diagonal_blocks(const SymmetricBlockMatrix& matrix, Eigen::Matrix3Xd& inverse) {
  const int nodes = matrix.node_count();
  inverse.resize(3, 3 * nodes);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    inverse.block<3, 3>(0, 3 * i) = full_block(matrix.block(matrix.diagonal[i])).inverse();
  }
}

}  // namespace

void AggregationMultigrid::set_operator(const SymmetricBlockMatrix& finest,
                                        std::uint64_t pattern_key) {
  m_finest = &finest;
  const bool new_pattern = m_levels.empty() || pattern_key != m_pattern_key;
  m_pattern_key = pattern_key;
  if (new_pattern) {
    m_levels.resize(1);
    for (int index = 0;; ++index) {
      const int nodes = matrix(index).node_count();
      if (nodes <= coarsest_nodes) break;
      MultigridLevel& fine = m_levels[index];
      const int coarse_nodes = aggregate_nodes(matrix(index), fine.aggregate);
      if (coarse_nodes == 0 || coarse_nodes * 5 > nodes * 4) break;  // no longer coarsening
      // each aggregate's nodes in node order: the restriction sums them in the order a serial
      // scatter would add them
      group_by_label(fine.aggregate, coarse_nodes, fine.member_start, fine.members);
      MultigridLevel coarse;
      build_summed_pattern(matrix(index), nullptr, &fine.aggregate, nodes, false, fine.prolongated,
                           fine.prolongated_block);
      build_summed_pattern(fine.prolongated, &fine.aggregate, nullptr, coarse_nodes, true,
                           coarse.matrix, fine.coarse_block);
      galerkin_product(matrix(index), fine, coarse.matrix);  // the next aggregation reads it
      m_levels.push_back(std::move(coarse));
    }
    m_levels.back().aggregate.clear();
    m_levels.back().member_start.clear();
    m_levels.back().members.clear();
    m_levels.back().prolongated = SymmetricBlockMatrix{};
  }
  for (int index = 0; index < static_cast<int>(m_levels.size()); ++index) {
    MultigridLevel& level = m_levels[index];
    if (index > 0) galerkin_product(matrix(index - 1), m_levels[index - 1], level.matrix);
    const Eigen::Index size = 3 * matrix(index).node_count();
    invert_diagonal_blocks(matrix(index), level.diagonal_inverse);
    level.solution.setZero(size);
    level.residual.setZero(size);
    level.right_side.setZero(size);
  }
  m_coarsest_matrix = to_sparse(matrix(static_cast<int>(m_levels.size()) - 1));
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
  // pre-smoothing from x = 0: x = omega D^-1 b, and r = b - A x
  jacobi_sweep(level, level.right_side, level.solution, false);
  symmetric_block_residual(matrix(index), level.right_side, level.solution, level.residual);
  // r_c = P^T r: each aggregate's residuals summed
  MultigridLevel& coarse = m_levels[index + 1];
  const int coarse_nodes = static_cast<int>(coarse.right_side.size() / 3);
#pragma omp parallel for schedule(static) if (coarse_nodes >= min_parallel_items)
  for (int a = 0; a < coarse_nodes; ++a) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k = level.member_start[a]; k < level.member_start[a + 1]; ++k)
      sum += level.residual.segment<3>(3 * level.members[k]);
    coarse.right_side.segment<3>(3 * a) = sum;
  }
  cycle(index + 1);
  // x += P e and r -= (A P) e: the residual at the corrected x without a product by A
  const int nodes = static_cast<int>(level.right_side.size() / 3);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    const int a = level.aggregate[i];
    if (a >= 0) level.solution.segment<3>(3 * i) += coarse.solution.segment<3>(3 * a);
  }
  symmetric_block_residual(level.prolongated, level.residual, coarse.solution, level.residual);
  jacobi_sweep(level, level.residual, level.solution, true);  // post-smoothing
}

void AggregationMultigrid::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  m_levels[0].right_side = r;
  cycle(0);
  z = m_levels[0].solution;
}

}  // namespace tissu
