#include "solver/forces/spring_block_matrix.hpp"

#include <gtest/gtest.h>

#include <random>

#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

// random symmetric 3x3 blocks, one per spring, and a random diagonal
void random_blocks(const SpringModel& model, std::vector<Eigen::Matrix3d>& blocks,
                   Eigen::VectorXd& diagonal) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  blocks.resize(model.spring_count());
  for (Eigen::Matrix3d& block : blocks) {
    for (int a = 0; a < 3; ++a) {
      for (int c = a; c < 3; ++c) block(a, c) = block(c, a) = unit(rng);
    }
  }
  diagonal.resize(model.particle_count());
  for (Eigen::Index p = 0; p < diagonal.size(); ++p) diagonal[p] = 2.0 + unit(rng);
}

std::vector<SymmetricBlock> upper_triangles(const std::vector<Eigen::Matrix3d>& blocks) {
  std::vector<SymmetricBlock> upper;
  for (const Eigen::Matrix3d& block : blocks) upper.push_back(upper_triangle(block));
  return upper;
}

// the same matrix assembled densely, spring by spring
Eigen::MatrixXd dense_reference(const SpringModel& model,
                                const std::vector<Eigen::Matrix3d>& blocks,
                                const Eigen::VectorXd& diagonal) {
  const int dofs = 3 * model.particle_count();
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(dofs, dofs);
  for (int p = 0; p < model.particle_count(); ++p) {
    matrix.block<3, 3>(3 * p, 3 * p) += diagonal[p] * Eigen::Matrix3d::Identity();
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const int i = model.springs(s, 0);
    const int j = model.springs(s, 1);
    matrix.block<3, 3>(3 * i, 3 * i) += blocks[s];
    matrix.block<3, 3>(3 * j, 3 * j) += blocks[s];
    matrix.block<3, 3>(3 * i, 3 * j) -= blocks[s];
    matrix.block<3, 3>(3 * j, 3 * i) -= blocks[s];
  }
  return matrix;
}

TEST(SpringBlockMatrix, MatchesADenseAssemblyInBothStorageOrders) {
  State state;
  // 40 springs on 8 particles: some pairs are joined twice
  const SpringModel model = test::random_model(8, 40, 0, 21, state);
  std::vector<Eigen::Matrix3d> blocks;
  Eigen::VectorXd diagonal;
  random_blocks(model, blocks, diagonal);
  SpringBlockPattern pattern;
  update_spring_block_pattern(model, pattern);
  Eigen::SparseMatrix<double, Eigen::ColMajor> column_major;
  Eigen::SparseMatrix<double, Eigen::RowMajor> row_major;
  assemble_spring_block_matrix(model, pattern, blocks, diagonal, false, column_major);
  assemble_spring_block_matrix(model, pattern, blocks, diagonal, false, row_major);
  SymmetricBlockMatrix symmetric;
  assemble_symmetric_spring_block_matrix(model, pattern, upper_triangles(blocks), diagonal, false,
                                         symmetric);
  const Eigen::MatrixXd expected = dense_reference(model, blocks, diagonal);
  EXPECT_LT((Eigen::MatrixXd(column_major) - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((Eigen::MatrixXd(row_major) - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((Eigen::MatrixXd(to_sparse(symmetric)) - expected).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(SpringBlockMatrix, SymmetricStorageFollowsANewPattern) {
  State state;
  const SpringModel first = test::random_model(8, 20, 0, 24, state);
  const SpringModel second = test::random_model(12, 30, 0, 25, state);
  SymmetricBlockMatrix reused;
  for (const SpringModel* model : {&first, &second}) {
    std::vector<Eigen::Matrix3d> blocks;
    Eigen::VectorXd diagonal;
    random_blocks(*model, blocks, diagonal);
    SpringBlockPattern pattern;
    update_spring_block_pattern(*model, pattern);
    SymmetricBlockMatrix fresh;
    assemble_symmetric_spring_block_matrix(*model, pattern, upper_triangles(blocks), diagonal, true,
                                           reused);
    assemble_symmetric_spring_block_matrix(*model, pattern, upper_triangles(blocks), diagonal, true,
                                           fresh);
    EXPECT_EQ(reused.columns, fresh.columns);
    EXPECT_EQ(reused.values, fresh.values);
  }
}

TEST(SpringBlockMatrix, FilterGivesSASPlusIMinusS) {
  State state;
  SpringModel model = test::random_model(8, 20, 0, 22, state);
  model.pinned[2] = 1;
  model.pinned[5] = 1;
  finalize_model(model);
  std::vector<Eigen::Matrix3d> blocks;
  Eigen::VectorXd diagonal;
  random_blocks(model, blocks, diagonal);
  SpringBlockPattern pattern;
  update_spring_block_pattern(model, pattern);
  Eigen::SparseMatrix<double> filtered;
  assemble_spring_block_matrix(model, pattern, blocks, diagonal, true, filtered);
  SymmetricBlockMatrix symmetric;
  assemble_symmetric_spring_block_matrix(model, pattern, upper_triangles(blocks), diagonal, true,
                                         symmetric);
  const int dofs = 3 * model.particle_count();
  Eigen::VectorXd s = Eigen::VectorXd::Ones(dofs);
  s.segment<3>(6).setZero();
  s.segment<3>(15).setZero();
  const Eigen::MatrixXd expected =
      s.asDiagonal() * dense_reference(model, blocks, diagonal) * s.asDiagonal() +
      Eigen::MatrixXd((Eigen::VectorXd::Ones(dofs) - s).asDiagonal());
  EXPECT_LT((Eigen::MatrixXd(filtered) - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((Eigen::MatrixXd(to_sparse(symmetric)) - expected).cwiseAbs().maxCoeff(), 1e-14);
  // the symmetric storage's products, against the same dense matrix
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(dofs, -1.0, 2.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(dofs, 3.0, -0.5);
  Eigen::VectorXd product, residual;
  symmetric_block_product(symmetric, x, product);
  symmetric_block_residual(symmetric, b, x, residual);
  EXPECT_LT((product - expected * x).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((residual - (b - expected * x)).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(SymmetricBlockMatrix, EveryKernelOfThisProcessorGivesTheProducts) {
  State state;
  const SpringModel model = test::random_model(300, 1500, 0, 26, state);
  std::vector<Eigen::Matrix3d> blocks;
  Eigen::VectorXd diagonal;
  random_blocks(model, blocks, diagonal);
  SpringBlockPattern pattern;
  update_spring_block_pattern(model, pattern);
  SymmetricBlockMatrix symmetric;
  assemble_symmetric_spring_block_matrix(model, pattern, upper_triangles(blocks), diagonal, false,
                                         symmetric);
  const Eigen::MatrixXd expected = dense_reference(model, blocks, diagonal);
  const int dofs = 3 * model.particle_count();
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(dofs, -1.0, 2.0).array().sin();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(dofs, 3.0, -0.5);
  std::vector<BlockProductKernel> kernels{BlockProductKernel::portable};
#if defined(__x86_64__)
  // the vectorised kernel is chosen exactly where the processor runs it
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  EXPECT_EQ(block_product_kernel(), avx2 ? BlockProductKernel::avx2 : BlockProductKernel::portable);
  if (avx2) kernels.push_back(BlockProductKernel::avx2);
#endif
  for (const BlockProductKernel kernel : kernels) {
    Eigen::VectorXd product, residual = b;
    symmetric_block_product(symmetric, x, product, kernel);
    symmetric_block_residual(symmetric, residual, x, residual, kernel);  // in place
    EXPECT_LT((product - expected * x).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((residual - (b - expected * x)).cwiseAbs().maxCoeff(), 1e-12);
  }
}

}  // namespace
}  // namespace tissu
