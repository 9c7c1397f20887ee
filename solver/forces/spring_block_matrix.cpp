#include "solver/forces/spring_block_matrix.hpp"

#include <algorithm>
#include <cassert>

#include "solver/parallel.hpp"

namespace tissu {
namespace {

void build_blocks(const SpringModel& model, SpringBlockPattern& pattern) {
  const int particles = model.particle_count();
  const ParticleSpringIncidence& incidence = model.incidence;
  pattern.block_offsets.assign(particles + 1, 0);
  pattern.block_columns.clear();
  pattern.diagonal_block.assign(particles, 0);
  pattern.incidence_block.assign(incidence.springs.size(), 0);
  std::vector<int> row;
  for (int i = 0; i < particles; ++i) {
    row.assign(1, i);
    for (int e = incidence.offsets[i]; e < incidence.offsets[i + 1]; ++e) {
      const int s = incidence.springs[e];
      row.push_back(model.springs(s, incidence.first_end[e] ? 1 : 0));
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    const int first = static_cast<int>(pattern.block_columns.size());
    pattern.block_columns.insert(pattern.block_columns.end(), row.begin(), row.end());
    pattern.block_offsets[i + 1] = static_cast<int>(pattern.block_columns.size());
    const auto slot = [&](int particle) {
      return first +
             static_cast<int>(std::lower_bound(row.begin(), row.end(), particle) - row.begin());
    };
    pattern.diagonal_block[i] = slot(i);
    for (int e = incidence.offsets[i]; e < incidence.offsets[i + 1]; ++e) {
      const int s = incidence.springs[e];
      pattern.incidence_block[e] = slot(model.springs(s, incidence.first_end[e] ? 1 : 0));
    }
  }
}

void build_scalar_indices(SpringBlockPattern& pattern) {
  const int particles = pattern.particle_count;
  pattern.outer.assign(3 * particles + 1, 0);
  pattern.inner.assign(9 * pattern.block_columns.size(), 0);
  for (int i = 0; i < particles; ++i) {
    const int first = pattern.block_offsets[i];
    const int blocks = pattern.block_offsets[i + 1] - first;
    for (int a = 0; a < 3; ++a) {
      const int row_start = 9 * first + 3 * blocks * a;
      pattern.outer[3 * i + a] = row_start;
      for (int n = 0; n < blocks; ++n) {
        for (int c = 0; c < 3; ++c) {
          pattern.inner[row_start + 3 * n + c] = 3 * pattern.block_columns[first + n] + c;
        }
      }
    }
  }
  pattern.outer[3 * particles] = static_cast<int>(pattern.inner.size());
}

// adds `sign` W to block `block` of block-row i, whose values start at `row_values`
void add_block(double* row_values, int blocks_in_row, int local_block, const Eigen::Matrix3d& w,
               double sign) {
  for (int a = 0; a < 3; ++a) {
    for (int c = 0; c < 3; ++c) {
      row_values[3 * blocks_in_row * a + 3 * local_block + c] += sign * w(a, c);
    }
  }
}

}  // namespace

void update_spring_block_pattern(const SpringModel& model, SpringBlockPattern& pattern) {
  assert(model.incidence.offsets.size() == static_cast<std::size_t>(model.particle_count()) + 1 &&
         "call finalize_model() first");
  if (pattern.built_for_model != 0 && pattern.built_for_model == model.identity) return;
  pattern.built_for_model = model.identity;
  pattern.particle_count = model.particle_count();
  build_blocks(model, pattern);
  build_scalar_indices(pattern);
}

template <int StorageOrder>
void assemble_spring_block_matrix(const SpringModel& model, const SpringBlockPattern& pattern,
                                  const std::vector<Eigen::Matrix3d>& spring_blocks,
                                  const Eigen::VectorXd& diagonal, bool filter_pinned,
                                  Eigen::SparseMatrix<double, StorageOrder>& matrix) {
  const int particles = pattern.particle_count;
  assert(particles == model.particle_count());
  const auto nonzeros = static_cast<Eigen::Index>(pattern.inner.size());
  // resize keeps the value and index storage; resizeNonZeros grows it only if needed
  matrix.resize(3 * particles, 3 * particles);
  matrix.resizeNonZeros(nonzeros);
  std::copy(pattern.outer.begin(), pattern.outer.end(), matrix.outerIndexPtr());
  std::copy(pattern.inner.begin(), pattern.inner.end(), matrix.innerIndexPtr());
  double* values = matrix.valuePtr();
  const ParticleSpringIncidence& incidence = model.incidence;

#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int i = 0; i < particles; ++i) {
    const int first = pattern.block_offsets[i];
    const int blocks = pattern.block_offsets[i + 1] - first;
    double* row_values = values + 9 * first;
    std::fill(row_values, row_values + 9 * blocks, 0.0);
    const int diagonal_local = pattern.diagonal_block[i] - first;
    const bool pinned_row = filter_pinned && model.inverse_mass[i] == 0.0;
    if (pinned_row) {
      add_block(row_values, blocks, diagonal_local, Eigen::Matrix3d::Identity(), 1.0);
      continue;
    }
    add_block(row_values, blocks, diagonal_local, diagonal[i] * Eigen::Matrix3d::Identity(), 1.0);
    for (int e = incidence.offsets[i]; e < incidence.offsets[i + 1]; ++e) {
      const Eigen::Matrix3d& w = spring_blocks[incidence.springs[e]];
      add_block(row_values, blocks, diagonal_local, w, 1.0);
      add_block(row_values, blocks, pattern.incidence_block[e] - first, w, -1.0);
    }
    if (filter_pinned) {
      for (int n = 0; n < blocks; ++n) {
        if (model.inverse_mass[pattern.block_columns[first + n]] != 0.0) continue;
        for (int a = 0; a < 3; ++a) {
          std::fill_n(row_values + 3 * blocks * a + 3 * n, 3, 0.0);
        }
      }
    }
  }
}

template void assemble_spring_block_matrix<Eigen::ColMajor>(
    const SpringModel&, const SpringBlockPattern&, const std::vector<Eigen::Matrix3d>&,
    const Eigen::VectorXd&, bool, Eigen::SparseMatrix<double, Eigen::ColMajor>&);
template void assemble_spring_block_matrix<Eigen::RowMajor>(
    const SpringModel&, const SpringBlockPattern&, const std::vector<Eigen::Matrix3d>&,
    const Eigen::VectorXd&, bool, Eigen::SparseMatrix<double, Eigen::RowMajor>&);

void assemble_symmetric_spring_block_matrix(const SpringModel& model,
                                            const SpringBlockPattern& pattern,
                                            const std::vector<SymmetricBlock>& spring_blocks,
                                            const Eigen::VectorXd& diagonal, bool filter_pinned,
                                            SymmetricBlockMatrix& matrix) {
  const int particles = pattern.particle_count;
  assert(particles == model.particle_count());
  if (matrix.pattern_key == 0 || matrix.pattern_key != pattern.built_for_model) {
    matrix.pattern_key = pattern.built_for_model;
    matrix.offsets = pattern.block_offsets;
    matrix.columns = pattern.block_columns;
    matrix.diagonal = pattern.diagonal_block;
    matrix.values.resize(6 * pattern.block_columns.size());
  }
  const ParticleSpringIncidence& incidence = model.incidence;
  const SymmetricBlock identity = upper_triangle(Eigen::Matrix3d::Identity());
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int i = 0; i < particles; ++i) {
    const int first = matrix.offsets[i];
    std::fill(&matrix.values[6 * first], &matrix.values[6 * matrix.offsets[i + 1]], 0.0);
    if (filter_pinned && model.inverse_mass[i] == 0.0) {
      matrix.block(matrix.diagonal[i]) = identity;
      continue;
    }
    SymmetricBlock diagonal_block = diagonal[i] * identity;
    for (int e = incidence.offsets[i]; e < incidence.offsets[i + 1]; ++e) {
      const SymmetricBlock& w = spring_blocks[incidence.springs[e]];
      diagonal_block += w;
      matrix.block(pattern.incidence_block[e]) -= w;
    }
    matrix.block(matrix.diagonal[i]) = diagonal_block;
    if (!filter_pinned) continue;
    for (int k = first; k < matrix.offsets[i + 1]; ++k) {
      if (model.inverse_mass[matrix.columns[k]] == 0.0) matrix.block(k).setZero();
    }
  }
}

}  // namespace tissu
