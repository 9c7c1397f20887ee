#include "solver/pd/pd_direct_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <vector>

#include "solver/parallel.hpp"
#include "solver/pd/nested_dissection_ordering.hpp"

namespace tissu {
namespace {

/// Threads for the two halves of a sweep: two, unless the user allows fewer (OMP_NUM_THREADS).
int half_threads() {
  return std::min(2, omp_get_max_threads());
}

}  // namespace

Eigen::SparseMatrix<double> pd_free_particle_matrix(const PdSystem& system) {
  const int free_count = static_cast<int>(system.free_particles.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(system.neighbours.size() + system.free_particles.size());
  for (int row = 0; row < free_count; ++row) {
    const int i = system.free_particles[row];
    entries.emplace_back(row, row, system.diagonal[i]);
    for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
      const int column = system.free_index[system.neighbours[e]];
      if (column >= 0) entries.emplace_back(row, column, -system.weights[e]);
    }
  }
  Eigen::SparseMatrix<double> matrix(free_count, free_count);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

bool PdDirectSolver::factorize(const PdSystem& system) {
  const bool settled = m_solves_on_factor >= solves_before_nested_dissection;
  if (m_ldlt && m_generation == system.generation && (m_nested_dissection || !settled)) {
    return true;
  }
  m_nested_dissection = m_ldlt && m_generation == system.generation;  // settled: reorder it
  const int free_count = static_cast<int>(system.free_particles.size());
  const Matrix matrix = pd_free_particle_matrix(system);
  // the orderings give P^-1 (new row -> row of A), as Eigen's factorisations expect them to
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
  if (m_nested_dissection) {
    NestedDissectionOrdering()(matrix, inverse);
  } else {
    Eigen::AMDOrdering<int>()(matrix, inverse);
  }
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation =
      inverse.inverse();
  m_permutation = permutation.indices();
  Matrix permuted(free_count, free_count);
  permuted.selfadjointView<Eigen::Lower>() =
      matrix.selfadjointView<Eigen::Lower>().twistedBy(permutation);
  if (!m_ldlt) m_ldlt = std::make_unique<Factorization>();
  m_ldlt->compute(permuted);
  ++m_factorizations;
  m_solves_on_factor = 0;
  if (m_ldlt->info() != Eigen::Success) {
    m_generation = 0;
    return false;
  }
  m_generation = system.generation;
  m_inverse_d = m_ldlt->vectorD().cwiseInverse();  // vectorD() returns a copy: keep it
  m_solution.resize(3, free_count);
  const Matrix& lower = m_ldlt->matrixL().nestedExpression();
  m_partition = partition_factor(free_count, lower.outerIndexPtr(), lower.innerIndexPtr());
  for (Eigen::Matrix3Xd& updates : m_separator_updates) {
    updates.resize(3, free_count - m_partition.separator_start);
  }
  if (m_precision == SolvePrecision::single) {
    m_values_single.assign(lower.valuePtr(), lower.valuePtr() + lower.nonZeros());
    m_inverse_d_single = m_inverse_d.cast<float>();
    for (Eigen::Matrix4Xf& updates : m_separator_updates_single) {
      updates.resize(4, free_count - m_partition.separator_start);
    }
  }
  return true;
}

template <class Scalar, int Rows>
void PdDirectSolver::sweep(
    const Scalar* values, const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& inverse_d,
    Eigen::Matrix<Scalar, Rows, Eigen::Dynamic>& solution,
    std::array<Eigen::Matrix<Scalar, Rows, Eigen::Dynamic>, 2>& separator_updates) const {
  const int free_count = static_cast<int>(solution.cols());
  const bool two_threads = free_count >= min_parallel_items;
  const int threads = half_threads();
  // L D L^T z = z in place, x, y and z of a particle together: each triangular sweep reads L
  // once for the three coordinates (Eigen's solveInPlace reads it once per right-hand side column)
  const Matrix& lower = m_ldlt->matrixL().nestedExpression();  // unit lower, CSC
  const int* outer = lower.outerIndexPtr();
  const int* inner = lower.innerIndexPtr();
  const FactorPartition& partition = m_partition;
  const int separator_start = partition.separator_start;

  // L y = z: each half scatters into its own rows and into its own copy of the separator rows
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (two_threads)
  for (int half = 0; half < 2; ++half) {
    auto& updates = separator_updates[half];
    updates.setZero();
    for (const int column : partition.half_columns[half]) {
      const auto y = solution.col(column).eval();
      const int separator_entry = partition.separator_entry[column];
      for (int k = partition.first_below_diagonal[column]; k < separator_entry; ++k) {
        solution.col(inner[k]) -= values[k] * y;
      }
      for (int k = separator_entry; k < outer[column + 1]; ++k) {
        updates.col(inner[k] - separator_start) -= values[k] * y;
      }
    }
  }
  for (int column = separator_start; column < free_count; ++column) {
    solution.col(column) += separator_updates[0].col(column - separator_start) +
                            separator_updates[1].col(column - separator_start);
    const auto y = solution.col(column).eval();
    for (int k = partition.first_below_diagonal[column]; k < outer[column + 1]; ++k) {
      solution.col(inner[k]) -= values[k] * y;
    }
  }
  solution.array().rowwise() *= inverse_d.transpose().array();  // D^-1

  // L^T x = y: the separator, then the halves, each reading its own rows and the separator's
  const auto solve_column_backward = [&](int column) {
    auto x = solution.col(column).eval();
    for (int k = partition.first_below_diagonal[column]; k < outer[column + 1]; ++k) {
      x -= values[k] * solution.col(inner[k]);
    }
    solution.col(column) = x;
  };
  for (int column = free_count - 1; column >= separator_start; --column) {
    solve_column_backward(column);
  }
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (two_threads)
  for (int half = 0; half < 2; ++half) {
    const std::vector<int>& columns = partition.half_columns[half];
    for (auto column = columns.rbegin(); column != columns.rend(); ++column) {
      solve_column_backward(*column);
    }
  }
}

bool PdDirectSolver::solve(const PdSystem& system, const Eigen::VectorXd& c, Eigen::VectorXd& p) {
  if (!factorize(system)) return false;
  ++m_solves_on_factor;
  const int free_count = static_cast<int>(system.free_particles.size());
  const Eigen::VectorXi& permutation = m_permutation;  // row -> permuted row
  // z = P b, b_row = c_i + sum over pinned neighbours j of s_ij p_j
#pragma omp parallel for schedule(static) if (free_count >= min_parallel_items)
  for (int row = 0; row < free_count; ++row) {
    const int i = system.free_particles[row];
    Eigen::Vector3d b = c.segment<3>(3 * i);
    for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
      const int j = system.neighbours[e];
      if (system.pinned[j]) b += system.weights[e] * p.segment<3>(3 * j);
    }
    m_solution.col(permutation[row]) = b;
  }
  if (m_precision == SolvePrecision::single) {
    m_solution_single.resize(4, free_count);
    m_solution_single.topRows<3>() = m_solution.cast<float>();
    m_solution_single.row(3).setZero();
    sweep(m_values_single.data(), m_inverse_d_single, m_solution_single,
          m_separator_updates_single);
    m_solution = m_solution_single.topRows<3>().cast<double>();
  } else {
    sweep(m_ldlt->matrixL().nestedExpression().valuePtr(), m_inverse_d, m_solution,
          m_separator_updates);
  }
#pragma omp parallel for schedule(static) if (free_count >= min_parallel_items)
  for (int row = 0; row < free_count; ++row) {
    p.segment<3>(3 * system.free_particles[row]) = m_solution.col(permutation[row]);
  }
  return true;
}

}  // namespace tissu
