#pragma once
/// \file
/// An algebraic multigrid V-cycle for the 3#P x 3#P systems of a spring network (Newton's
/// Hessian): aggregation of the particle graph, coarse operators by Galerkin products, damped 3x3
/// block-Jacobi smoothing. A preconditioner for the conjugate gradient whose work per cycle is
/// linear in the particle count, and whose coarse levels see the Hessian's anisotropy (a taut
/// cloth far softer across its springs than along them), which the PD matrix cannot (Vanek,
/// Mandel & Brezina 1996 for the aggregation; Tamstorf, Jones & McCormick 2015 for multigrid on
/// cloth). Every level is stored in symmetric 3x3 blocks (symmetric_block_matrix.hpp). On the
/// stiff sheet the V-cycles per step grow from 28 to 39 from 81 x 81 to 512 x 512 particles
/// (docs/benchmarks.md).

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <vector>

#include "solver/forces/symmetric_block_matrix.hpp"

namespace tissu {

/// One level of the hierarchy: its operator (3n x 3n), the map of its nodes to the next level's
/// and the inverses of its 3x3 diagonal blocks.
struct MultigridLevel {
  SymmetricBlockMatrix matrix;         ///< 3n x 3n, levels 1 and up (level 0: A)
  std::vector<int> aggregate;          ///< n: node of the next level it belongs to, -1 for none
  std::vector<int> member_start;       ///< n_c + 1: aggregate a's nodes in `members` (offsets)
  std::vector<int> members;            ///< the aggregated nodes by aggregate, each in node order
  SymmetricBlockMatrix prolongated;    ///< A P, n x n_c: block (i, a) sums A_ij over j in a
  std::vector<int> prolongated_block;  ///< #blocks of A: block of A P each adds to (-1: none)
  std::vector<int> coarse_block;       ///< #blocks of A P: block of the next level's each adds to
  Eigen::Matrix3Xd diagonal_inverse;   ///< 3 x 3n: inverse of each node's diagonal block
  Eigen::VectorXd solution, residual, right_side;  ///< 3n scratch of the cycle
};

/// The hierarchy of one operator A, set by set_operator(); apply() runs one V-cycle: a damped
/// block-Jacobi sweep, the residual restricted to the aggregates (summed), the next level's cycle
/// prolongated back (piecewise constant), another sweep; the coarsest level solved by LDL^T. The
/// second sweep's residual is updated by A P (a few blocks per row) rather than recomputed by A:
/// one product by A per level and cycle instead of two, 11 % off Newton's time at 81 x 81. The
/// cycle is symmetric, and positive definite when A is: a preconditioner for the conjugate
/// gradient. Deterministic for any number of OpenMP threads.
class AggregationMultigrid {
 public:
  /// Builds the hierarchy for A (3n x 3n, symmetric positive definite), which must outlive the
  /// calls to apply(): the aggregates and the coarse patterns when `pattern_key` differs from the
  /// last call's (a key that changes whenever A's pattern does), the coarse operators' values and
  /// the smoothers always. Nodes whose row is the identity's with no coupling (pinned particles)
  /// are left out of the aggregates.
  void set_operator(const SymmetricBlockMatrix& matrix, std::uint64_t pattern_key);

  /// z = one V-cycle applied to r (3n each): an approximation of A^-1 r.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z);

  int level_count() const { return static_cast<int>(m_levels.size()); }
  int node_count(int level) const { return matrix(level).node_count(); }

 private:
  void cycle(int level);
  const SymmetricBlockMatrix& matrix(int level) const {
    return level == 0 ? *m_finest : m_levels[level].matrix;
  }
  const SymmetricBlockMatrix* m_finest = nullptr;
  std::uint64_t m_pattern_key = 0;
  std::vector<MultigridLevel> m_levels;
  Eigen::SparseMatrix<double> m_coarsest_matrix;  // column-major copy of the coarsest level
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> m_coarsest;  // movable
};

}  // namespace tissu
