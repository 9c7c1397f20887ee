#include "solver/forces/symmetric_block_matrix.hpp"

#include <algorithm>

#include "solver/parallel.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

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

/// r = b - A x (or A x with b null), row by row with block_row_product.
void portable_rows(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd* b,
                   const Eigen::VectorXd& x, Eigen::VectorXd& r) {
  const int nodes = matrix.row_count();
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int i = 0; i < nodes; ++i) {
    const Eigen::Vector3d y = block_row_product(matrix, i, x);
    r.segment<3>(3 * i) = b ? Eigen::Vector3d(b->segment<3>(3 * i) - y) : y;
  }
}

#if defined(__x86_64__)
/// Rows [first, last) of portable_rows() in AVX2 registers: block j's three columns (a0 a1 a2),
/// (a1 a3 a4), (a2 a4 a5), each read from the block's six values by two overlapping loads and a
/// shuffle, times x_j's coordinates, summed into three accumulators (lane 3 unused). Six loads and
/// three fused multiply-adds a block, against eighteen scalar operations. No OpenMP inside: clang
/// does not give a parallel region's body its function's target.
__attribute__((target("avx2,fma"))) void avx2_row_range(const SymmetricBlockMatrix& matrix,
                                                        const Eigen::VectorXd* b,
                                                        const Eigen::VectorXd& x,
                                                        Eigen::VectorXd& r, int first, int last) {
  const int* columns = matrix.columns.data();
  const double* values = matrix.values.data();
  for (int i = first; i < last; ++i) {
    __m256d sum0 = _mm256_setzero_pd(), sum1 = _mm256_setzero_pd(), sum2 = _mm256_setzero_pd();
    for (int k = matrix.offsets[i]; k < matrix.offsets[i + 1]; ++k) {
      const double* xj = x.data() + 3 * columns[k];
      const double* a = values + 6 * k;
      const __m256d a0123 = _mm256_loadu_pd(a), a2345 = _mm256_loadu_pd(a + 2);
      const __m256d column1 =  // (a1, a3, a4, a3)
          _mm256_blend_pd(_mm256_permute4x64_pd(a0123, 0b11111101), a2345, 0b0100);
      const __m256d column2 = _mm256_permute4x64_pd(a2345, 0b11111000);  // (a2, a4, a5, a5)
      sum0 = _mm256_fmadd_pd(a0123, _mm256_broadcast_sd(xj), sum0);
      sum1 = _mm256_fmadd_pd(column1, _mm256_broadcast_sd(xj + 1), sum1);
      sum2 = _mm256_fmadd_pd(column2, _mm256_broadcast_sd(xj + 2), sum2);
    }
    alignas(32) double y[4];
    _mm256_store_pd(y, _mm256_add_pd(_mm256_add_pd(sum0, sum1), sum2));
    for (int c = 0; c < 3; ++c) r[3 * i + c] = b ? (*b)[3 * i + c] - y[c] : y[c];
  }
}

/// avx2_row_range() over all rows, in chunks in parallel.
void avx2_rows(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd* b,
               const Eigen::VectorXd& x, Eigen::VectorXd& r) {
  constexpr int rows_per_chunk = 64;
  const int nodes = matrix.row_count();
  const int chunks = (nodes + rows_per_chunk - 1) / rows_per_chunk;
#pragma omp parallel for schedule(static) if (nodes >= min_parallel_items)
  for (int c = 0; c < chunks; ++c) {
    avx2_row_range(matrix, b, x, r, c * rows_per_chunk, std::min(nodes, (c + 1) * rows_per_chunk));
  }
}
#endif

void rows(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd* b, const Eigen::VectorXd& x,
          Eigen::VectorXd& r, BlockProductKernel kernel) {
  r.resize(3 * matrix.row_count());
#if defined(__x86_64__)
  if (kernel == BlockProductKernel::avx2) return avx2_rows(matrix, b, x, r);
#endif
  portable_rows(matrix, b, x, r);
}

}  // namespace

BlockProductKernel block_product_kernel() {
#if defined(__x86_64__)
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (avx2) return BlockProductKernel::avx2;
#endif
  return BlockProductKernel::portable;
}

void symmetric_block_product(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd& x,
                             Eigen::VectorXd& y, BlockProductKernel kernel) {
  rows(matrix, nullptr, x, y, kernel);
}

void symmetric_block_residual(const SymmetricBlockMatrix& matrix, const Eigen::VectorXd& b,
                              const Eigen::VectorXd& x, Eigen::VectorXd& r,
                              BlockProductKernel kernel) {
  rows(matrix, &b, x, r, kernel);
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
