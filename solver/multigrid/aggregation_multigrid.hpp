#pragma once
/// \file
/// An algebraic multigrid V-cycle for the 3#P x 3#P systems of a spring network (Newton's
/// Hessian): aggregation of the particle graph, coarse operators by Galerkin products, damped 3x3
/// block-Jacobi smoothing. A preconditioner for the conjugate gradient whose work per cycle is
/// linear in the particle count, and whose coarse levels see the Hessian's anisotropy (a taut
/// cloth far softer across its springs than along them), which the PD matrix cannot (Vanek,
/// Mandel & Brezina 1996 for the aggregation; Tamstorf, Jones & McCormick 2015 for multigrid on
/// cloth). On the stiff sheet the V-cycles per step grow from 28 to 47 from 81 x 81 to 512 x 512
/// particles (docs/benchmarks.md).

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <vector>

namespace tissu {

/// True when `matrix` (row-major, 3n x 3n) is made of full 3x3 blocks: rows 3i, 3i+1 and 3i+2
/// hold the same columns, in triples 3j, 3j+1, 3j+2 (spring_block_matrix.hpp's matrices, and the
/// coarse levels built from them).
bool has_3x3_block_rows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& matrix);

/// r = b - A x for a matrix of full 3x3 blocks (has_3x3_block_rows()): each block's column index
/// read once for its three rows, the rows in parallel (the same bits on any thread count).
/// Allocates nothing once r is sized.
void block_residual(const Eigen::SparseMatrix<double, Eigen::RowMajor>& matrix,
                    const Eigen::VectorXd& b, const Eigen::VectorXd& x, Eigen::VectorXd& r);

/// y = A x for a matrix of full 3x3 blocks, as block_residual().
void block_product(const Eigen::SparseMatrix<double, Eigen::RowMajor>& matrix,
                   const Eigen::VectorXd& x, Eigen::VectorXd& y);

/// One level of the hierarchy: its operator (3n x 3n, row-major), the map of its nodes to the
/// next level's and the inverses of its 3x3 diagonal blocks.
struct MultigridLevel {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;  ///< 3n x 3n, levels 1 and up (0: A's)
  std::vector<int> aggregate;         ///< n: node of the next level it belongs to, -1 for none
  std::vector<int> coarse_entry;      ///< nnz: entry of the next level's matrix each entry adds to
  Eigen::Matrix3Xd diagonal_inverse;  ///< 3 x 3n: inverse of each node's diagonal block
  Eigen::VectorXd solution, residual, right_side;  ///< 3n scratch of the cycle
};

/// The hierarchy of one operator A, set by set_operator(); apply() runs one V-cycle: a damped
/// block-Jacobi sweep, the residual restricted to the aggregates (summed), the next level's cycle
/// prolongated back (piecewise constant), another sweep; the coarsest level solved by LDL^T. The
/// cycle is symmetric, and positive definite when A is: a preconditioner for the conjugate
/// gradient. Deterministic for any number of OpenMP threads.
class AggregationMultigrid {
 public:
  /// Builds the hierarchy for A (3n x 3n, symmetric positive definite, 3x3 block structure),
  /// which must outlive the calls to apply(): the aggregates and the coarse patterns when
  /// `pattern_key` differs from the last call's (a key that changes whenever A's pattern does),
  /// the coarse operators' values and the smoothers always. Nodes whose row is the identity's
  /// with no coupling (pinned particles) are left out of the aggregates.
  void set_operator(const Eigen::SparseMatrix<double, Eigen::RowMajor>& matrix,
                    std::uint64_t pattern_key);

  /// z = one V-cycle applied to r (3n each): an approximation of A^-1 r.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z);

  int level_count() const { return static_cast<int>(m_levels.size()); }
  int node_count(int level) const { return static_cast<int>(m_levels[level].matrix.rows() / 3); }

 private:
  void cycle(int level);
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& matrix(int level) const {
    return level == 0 ? *m_finest : m_levels[level].matrix;
  }
  const Eigen::SparseMatrix<double, Eigen::RowMajor>* m_finest = nullptr;
  std::uint64_t m_pattern_key = 0;
  std::vector<MultigridLevel> m_levels;
  Eigen::SparseMatrix<double> m_coarsest_matrix;  // column-major copy of the coarsest level
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> m_coarsest;  // movable
};

}  // namespace tissu
