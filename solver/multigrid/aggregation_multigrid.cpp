#include "solver/multigrid/aggregation_multigrid.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>

#include "solver/parallel.hpp"

namespace tissu {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Chosen on the stiff hanging sheet at 81 x 81 (docs/benchmarks.md, "Newton preconditioned by
// multigrid"): one sweep before and after the coarse level ran in 53 ms per frame, two in 79 ms
// (fewer iterations, each dearer), three in 97 ms (omega 0.6); omega 0.5, 0.6, 0.7, 0.8 and 0.9
// took 40.6, 32.1, 33.7, 28.1 and 31.5 V-cycles per step.
constexpr int coarsest_nodes = 64;      // a level this small is solved exactly
constexpr int smoothing_sweeps = 1;     // block-Jacobi sweeps before and after the coarse level
constexpr double jacobi_damping = 0.8;  // omega of the damped block-Jacobi smoother
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

// the inverse of each node's diagonal block of a matrix of full 3x3 blocks
void invert_diagonal_blocks(const RowMatrix& matrix, Eigen::Matrix3Xd& inverse) {
  const int nodes = static_cast<int>(matrix.rows() / 3);
  inverse.resize(3, 3 * nodes);
  const int* outer = matrix.outerIndexPtr();
  const int* inner = matrix.innerIndexPtr();
  const double* values = matrix.valuePtr();
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    const int first = outer[3 * i];
    const int length = outer[3 * i + 1] - first;
    const int k = static_cast<int>(std::lower_bound(inner + first, inner + first + length, 3 * i) -
                                   (inner + first));
    Eigen::Matrix3d block;
    for (int d = 0; d < 3; ++d) {
      block.row(d) = Eigen::Map<const Eigen::RowVector3d>(values + first + d * length + k);
    }
    inverse.block<3, 3>(0, 3 * i) = block.inverse();
  }
}

// x += omega D^-1 (b - A x), with r = b - A x left in `residual`
void jacobi_sweep(const RowMatrix& matrix, const MultigridLevel& level, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x, Eigen::VectorXd& residual) {
  block_residual(matrix, b, x, residual);
  const int nodes = static_cast<int>(x.size() / 3);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    x.segment<3>(3 * i) += jacobi_damping * (level.diagonal_inverse.block<3, 3>(0, 3 * i) *
                                             residual.segment<3>(3 * i));
  }
}

}  // namespace

bool has_3x3_block_rows(const RowMatrix& matrix) {
  if (matrix.rows() % 3 != 0 || matrix.rows() != matrix.cols() || !matrix.isCompressed()) {
    return false;
  }
  const int* outer = matrix.outerIndexPtr();
  const int* inner = matrix.innerIndexPtr();
  for (Eigen::Index i = 0; i < matrix.rows() / 3; ++i) {
    const int first = outer[3 * i];
    const int length = outer[3 * i + 1] - first;
    if (length % 3 != 0) return false;
    for (int row = 1; row < 3; ++row) {
      const int start = outer[3 * i + row];
      if (outer[3 * i + row + 1] - start != length ||
          !std::equal(inner + first, inner + first + length, inner + start)) {
        return false;
      }
    }
    for (int k = 0; k < length; k += 3) {
      const int column = inner[first + k];
      if (column % 3 != 0 || inner[first + k + 1] != column + 1 ||
          inner[first + k + 2] != column + 2) {
        return false;
      }
    }
  }
  return true;
}

namespace {

// (A x)_i, the block row of node i of a matrix of full 3x3 blocks
inline Eigen::Vector3d block_row_product(const RowMatrix& matrix, int i, const Eigen::VectorXd& x) {
  const int* outer = matrix.outerIndexPtr();
  const int first = outer[3 * i];
  const int length = outer[3 * i + 1] - first;
  const int* columns = matrix.innerIndexPtr() + first;
  const double* row0 = matrix.valuePtr() + first;
  const double* row1 = row0 + length;
  const double* row2 = row1 + length;
  double y0 = 0.0, y1 = 0.0, y2 = 0.0;
  for (int k = 0; k < length; k += 3) {
    const double* xj = x.data() + columns[k];
    y0 += row0[k] * xj[0] + row0[k + 1] * xj[1] + row0[k + 2] * xj[2];
    y1 += row1[k] * xj[0] + row1[k + 1] * xj[1] + row1[k + 2] * xj[2];
    y2 += row2[k] * xj[0] + row2[k + 1] * xj[1] + row2[k + 2] * xj[2];
  }
  return {y0, y1, y2};
}

}  // namespace

void block_residual(const RowMatrix& matrix, const Eigen::VectorXd& b, const Eigen::VectorXd& x,
                    Eigen::VectorXd& r) {
  const int nodes = static_cast<int>(matrix.rows() / 3);
  r.resize(matrix.rows());
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    r.segment<3>(3 * i) = b.segment<3>(3 * i) - block_row_product(matrix, i, x);
  }
}

void block_product(const RowMatrix& matrix, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  const int nodes = static_cast<int>(matrix.rows() / 3);
  y.resize(matrix.rows());
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) y.segment<3>(3 * i) = block_row_product(matrix, i, x);
}

void AggregationMultigrid::set_operator(const RowMatrix& finest, std::uint64_t pattern_key) {
  m_finest = &finest;
  const bool new_pattern = m_levels.empty() || pattern_key != m_pattern_key;
  m_pattern_key = pattern_key;
  if (new_pattern) {
    if (!has_3x3_block_rows(finest)) {
      throw std::invalid_argument("AggregationMultigrid: expected a matrix of full 3x3 blocks");
    }
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
  block_residual(matrix(index), level.right_side, level.solution, level.residual);
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
