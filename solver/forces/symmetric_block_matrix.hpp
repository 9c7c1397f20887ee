#pragma once
/// \file
/// Symmetric 3n x 3n matrices made of symmetric 3x3 blocks, in block-compressed rows: a spring
/// network's stiffness (every spring's block k-weighted outer products, symmetric) and the
/// Galerkin coarse operators built from it. Six values per block instead of Eigen's nine and a
/// column index per block instead of one per scalar: 52 bytes per block against 108 in Eigen's
/// scalar CSR. The products stream the whole matrix, so that sets their speed once it no longer
/// fits in the caches: Newton on the stiff sheet of 128 x 128 particles ran 2.2 times faster when
/// its Hessian moved to this storage (docs/benchmarks.md).

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

namespace tissu {

/// Upper triangle of a symmetric 3x3 block, (xx, xy, xz, yy, yz, zz).
using SymmetricBlock = Eigen::Matrix<double, 6, 1>;

/// A symmetric matrix of symmetric 3x3 blocks (A_ij = A_ij^T = A_ji). Block row i holds blocks
/// [offsets[i], offsets[i+1]), in ascending columns[], the diagonal one among them. The same
/// storage holds rectangular matrices of symmetric blocks (no diagonal), such as A P in the
/// multigrid, whose rows sum blocks of A.
struct SymmetricBlockMatrix {
  std::uint64_t pattern_key = 0;  ///< identity of the pattern it was built on (0 = none)
  std::vector<int> offsets;       ///< n+1
  std::vector<int> columns;       ///< #blocks, node of each block, ascending in a row
  std::vector<int> diagonal;      ///< n, index of block (i, i)
  std::vector<double> values;     ///< 6 #blocks, each block's upper triangle (SymmetricBlock)

  int node_count() const { return static_cast<int>(diagonal.size()); }  ///< square: n
  int row_count() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
  int block_count() const { return static_cast<int>(columns.size()); }
  Eigen::Map<SymmetricBlock> block(int k) { return Eigen::Map<SymmetricBlock>(&values[6 * k]); }
  Eigen::Map<const SymmetricBlock> block(int k) const {
    return Eigen::Map<const SymmetricBlock>(&values[6 * k]);
  }
};

/// The upper triangle of a symmetric 3x3 matrix.
inline SymmetricBlock upper_triangle(const Eigen::Matrix3d& m) {
  return (SymmetricBlock() << m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)).finished();
}

/// The full 3x3 matrix of a block's upper triangle.
inline Eigen::Matrix3d full_block(const SymmetricBlock& b) {
  return (Eigen::Matrix3d() << b[0], b[1], b[2], b[1], b[3], b[4], b[2], b[4], b[5]).finished();
}

/// The code the products run: AVX2 with fused multiply-adds where the processor has them (the
/// products 1.5 times faster on the stiff sheet's Hessian at 81 x 81 and 128 x 128, where it fits
/// in the caches; docs/benchmarks.md), else portable scalar code. The two round differently, so a
/// run's bits depend on the processor, never on the number of threads.
enum class BlockProductKernel { portable, avx2 };

/// AVX2 if this processor has it (and fused multiply-adds), else portable.
BlockProductKernel block_product_kernel();

/// y = A x (3 rows and 3 columns' worth each). Rows in parallel: the same bits on any number of
/// threads. Allocates nothing once y is sized.
void symmetric_block_product(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd& x,
                             Eigen::VectorXd& y,
                             BlockProductKernel kernel = block_product_kernel());

/// r = b - A x, as symmetric_block_product(); r may be b (an update in place).
void symmetric_block_residual(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd& b,
                              const Eigen::VectorXd& x, Eigen::VectorXd& r,
                              BlockProductKernel kernel = block_product_kernel());

/// The same matrix in Eigen's scalar storage (for direct solvers and tests).
Eigen::SparseMatrix<double> to_sparse(const SymmetricBlockMatrix& matrix);

}  // namespace tissu
