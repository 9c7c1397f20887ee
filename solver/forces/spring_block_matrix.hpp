#pragma once
/// \file
/// Block-sparse 3#P x 3#P matrices with the structure of a spring network (force Jacobians, the
/// implicit integrator's system matrix), assembled deterministically and without allocation once
/// the pattern is known.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "solver/forces/symmetric_block_matrix.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Symmetric sparsity pattern: one 3x3 block on the diagonal of each particle and one for each
/// pair of particles joined by at least one spring. Because it is symmetric, the same index
/// arrays describe the matrix in row-major (CSR) and column-major (CSC) storage.
struct SpringBlockPattern {
  std::uint64_t built_for_model = 0;  ///< SpringModel::identity it was built from (0 = none)
  int particle_count = 0;             ///< #P the pattern was built for
  std::vector<int> block_offsets;     ///< #P+1, blocks of block-row i: [offsets[i], offsets[i+1])
  std::vector<int> block_columns;     ///< #blocks particle id of each block, ascending in a row
  std::vector<int> diagonal_block;    ///< #P index of block (i, i) in block_columns
  std::vector<int> incidence_block;   ///< #incidences index of block (i, other end of the spring)
  std::vector<int> outer;             ///< 3#P+1 first scalar entry of each scalar row
  std::vector<int> inner;             ///< #nonzeros scalar column of each entry, ascending
};

/// Rebuilds `pattern` from model.springs and model.incidence unless it was already built for this
/// model (SpringModel::identity).
void update_spring_block_pattern(const SpringModel& model, SpringBlockPattern& pattern);

/// Fills `matrix` (3#P x 3#P) on `pattern` with the symmetric block Laplacian of the springs:
/// block(i, i) = diagonal_i I + sum over springs s of i of W_s,
/// block(i, j) = -sum over springs s joining i and j of W_s,
/// where W_s = spring_blocks[s] is a symmetric 3x3 block and diagonal is #P (same unit as W).
/// With filter_pinned, the rows and columns of particles with inverse_mass 0 are replaced by those
/// of the identity: the matrix becomes S A S + (I - S), S = diag(1 free, 0 pinned). Particle rows
/// are filled in parallel, each summing its springs in model.incidence order: deterministic.
/// Defined for Eigen::ColMajor and Eigen::RowMajor storage.
template <int StorageOrder>
void assemble_spring_block_matrix(const SpringModel& model, const SpringBlockPattern& pattern,
                                  const std::vector<Eigen::Matrix3d>& spring_blocks,
                                  const Eigen::VectorXd& diagonal, bool filter_pinned,
                                  Eigen::SparseMatrix<double, StorageOrder>& matrix);

/// The same matrix as assemble_spring_block_matrix(), in symmetric block storage, from the upper
/// triangles of the springs' blocks: half the memory traffic of its products. Copies the
/// pattern's indices only when `matrix` was built on another pattern.
void assemble_symmetric_spring_block_matrix(const SpringModel& model,
                                            const SpringBlockPattern& pattern,
                                            const std::vector<SymmetricBlock>& spring_blocks,
                                            const Eigen::VectorXd& diagonal, bool filter_pinned,
                                            SymmetricBlockMatrix& matrix);

}  // namespace tissu
