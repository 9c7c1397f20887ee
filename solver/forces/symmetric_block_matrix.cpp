#include "solver/forces/symmetric_block_matrix.hpp"

#include "solver/parallel.hpp"

namespace tissu {
namespace {

// (A x)_i, block row i
inline Eigen::Vector3d block_row_product(const SymmetricBlockMatrix& matrix, int i,
                                         const Eigen::VectorXd& x) {
  const int* columns = matrix.columns.data();
  const double* values = matrix.values.data();
  double y0 = 0.0, y1 = 0.0, y2 = 0.0;
  for (int k = matrix.offsets[i]; k < matrix.offsets[i + 1]; ++k) {
    const double* xj = x.data() + 3 * columns[k];
    const double* a = values + 6 * k;
    y0 += a[0] * xj[0] + a[1] * xj[1] + a[2] * xj[2];
    y1 += a[1] * xj[0] + a[3] * xj[1] + a[4] * xj[2];
    y2 += a[2] * xj[0] + a[4] * xj[1] + a[5] * xj[2];
  }
  return {y0, y1, y2};
}

}  // namespace

void symmetric_block_product(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd& x,
                             Eigen::VectorXd& y) {
  const int nodes = matrix.row_count();
  y.resize(3 * nodes);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) y.segment<3>(3 * i) = block_row_product(matrix, i, x);
}

void symmetric_block_residual(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd& b,
                              const Eigen::VectorXd& x, Eigen::VectorXd& r) {
  const int nodes = matrix.row_count();
  r.resize(3 * nodes);
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    r.segment<3>(3 * i) = b.segment<3>(3 * i) - block_row_product(matrix, i, x);
  }
}

Eigen::SparseMatrix<double> to_sparse(const SymmetricBlockMatrix& matrix) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * matrix.columns.size());
  for (int i = 0; i < matrix.node_count(); ++i) {
    for (int k = matrix.offsets[i]; k < matrix.offsets[i + 1]; ++k) {
      const Eigen::Matrix3d block = full_block(matrix.block(k));
      for (int a = 0; a < 3; ++a) {
        for (int c = 0; c < 3; ++c) {
          entries.emplace_back(3 * i + a, 3 * matrix.columns[k] + c, block(a, c));
        }
      }
    }
  }
  Eigen::SparseMatrix<double> sparse(3 * matrix.node_count(), 3 * matrix.node_count());
  sparse.setFromTriplets(entries.begin(), entries.end());
  return sparse;
}

}  // namespace tissu
