// The two halves of a factor never touch each other's rows, cover every column with the
// separator, and share the work about evenly on a cloth grid ordered by nested dissection.

#include "solver/pd/factor_partition.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <csignal>
#include <numeric>

#include "solver/pd/nested_dissection_ordering.hpp"
#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_system.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

using Matrix = Eigen::SparseMatrix<double>;
using Factorization = Eigen::SimplicialLDLT<Matrix, Eigen::Lower, NestedDissectionOrdering>;

// checks the partition's promises against the factor L; returns each half's entries
std::array<long, 2> expect_valid_partition(const Matrix& lower, const FactorPartition& partition) {
  const int columns = static_cast<int>(lower.cols());
  const int* outer = lower.outerIndexPtr();
  const int* rows = lower.innerIndexPtr();
  std::vector<int> half_of(columns, -1);  // -1: separator
  std::array<long, 2> entries{0, 0};
  int counted = columns - partition.separator_start;
  for (int half = 0; half < 2; ++half) {
    const std::vector<int>& list = partition.half_columns[half];
    EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
    for (const int column : list) {
      EXPECT_LT(column, partition.separator_start);
      EXPECT_EQ(half_of[column], -1) << "column " << column << " in both halves";
      half_of[column] = half;
      entries[half] += outer[column + 1] - outer[column];
    }
    counted += static_cast<int>(list.size());
  }
  EXPECT_EQ(counted, columns);  // every column once
  for (int column = 0; column < partition.separator_start; ++column) {
    const int below = partition.first_below_diagonal[column];
    const int separator = partition.separator_entry[column];
    EXPECT_LE(below, separator);
    for (int k = below; k < outer[column + 1]; ++k) {
      EXPECT_GT(rows[k], column);
      if (k < separator) {  // a row of the column's own half, never of the other one
        EXPECT_EQ(half_of[rows[k]], half_of[column]) << "column " << column << " row " << rows[k];
      } else {
        EXPECT_GE(rows[k], partition.separator_start);
      }
    }
  }
  return entries;
}

TEST(FactorPartition, SplitsANestedDissectionGridFactorIntoTwoBalancedIndependentHalves) {
  State state;
  SpringModel model = test::grid_model(41, 41, 0.025, 0.001, 3000.0, 0.0, state);
  model.pinned[0] = model.pinned[40] = 1;
  finalize_model(model);
  PdSystem system;
  update_pd_system(model, 1.0 / 30.0, system);
  Factorization ldlt(pd_free_particle_matrix(system));
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  const Matrix& lower = ldlt.matrixL().nestedExpression();
  const FactorPartition partition = partition_factor(static_cast<int>(lower.cols()),
                                                     lower.outerIndexPtr(), lower.innerIndexPtr());
  const std::array<long, 2> entries = expect_valid_partition(lower, partition);
  const long all = lower.nonZeros();
  EXPECT_GT(std::min(entries[0], entries[1]), all / 3);  // about half each
  EXPECT_LT(all - entries[0] - entries[1], all / 10);    // a small separator
}

// a factor given by its columns' rows (the diagonal included), as a sparse matrix
Matrix lower_factor(int columns, const std::vector<std::vector<int>>& column_rows) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int column = 0; column < columns; ++column) {
    for (const int row : column_rows[column]) entries.emplace_back(row, column, 1.0);
  }
  Matrix lower(columns, columns);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}

TEST(FactorPartition, DisconnectedPiecesHaveNoSeparator) {
  // two pieces: columns 0-2 (a chain 0 -> 1 -> 2) and 3-4 (3 -> 4)
  const Matrix lower = lower_factor(5, {{0, 1, 2}, {1, 2}, {2}, {3, 4}, {4}});
  const FactorPartition partition =
      partition_factor(5, lower.outerIndexPtr(), lower.innerIndexPtr());
  EXPECT_EQ(partition.separator_start, 5);
  expect_valid_partition(lower, partition);
  EXPECT_EQ(partition.half_columns[0], (std::vector<int>{0, 1, 2}));  // the heavier piece first
  EXPECT_EQ(partition.half_columns[1], (std::vector<int>{3, 4}));
}

TEST(FactorPartition, AChainIsAllSeparator) {
  const Matrix lower = lower_factor(4, {{0, 1}, {1, 2, 3}, {2, 3}, {3}});
  const FactorPartition partition =
      partition_factor(4, lower.outerIndexPtr(), lower.innerIndexPtr());
  EXPECT_EQ(partition.separator_start, 0);
  EXPECT_TRUE(partition.half_columns[0].empty());
  EXPECT_TRUE(partition.half_columns[1].empty());
}

TEST(FactorPartition, AnEmptyFactorHasNothingToSplit) {
  const Matrix lower(0, 0);
  const FactorPartition partition =
      partition_factor(0, lower.outerIndexPtr(), lower.innerIndexPtr());
  EXPECT_EQ(partition.separator_start, 0);
  EXPECT_TRUE(partition.half_columns[0].empty() && partition.half_columns[1].empty());
}

TEST(NestedDissectionOrdering, GivesAPermutationAndFallsBackOnGraphsWithoutEdges) {
  for (const int size : {0, 1, 2, 5, 300}) {
    Matrix diagonal(size, size);
    diagonal.setIdentity();
    Matrix path = diagonal;  // a path graph 0 - 1 - ... (no edge below 2 vertices)
    for (int i = 0; i + 1 < size; ++i) {
      path.coeffRef(i, i + 1) = path.coeffRef(i + 1, i) = -0.5;
    }
    for (const Matrix& matrix : {diagonal, path}) {
      NestedDissectionOrdering::PermutationType permutation;
      NestedDissectionOrdering()(matrix, permutation);
      std::vector<int> indices(permutation.indices().data(),
                               permutation.indices().data() + permutation.size());
      std::sort(indices.begin(), indices.end());
      std::vector<int> expected(size);
      std::iota(expected.begin(), expected.end(), 0);
      EXPECT_EQ(indices, expected) << "size " << size;
    }
  }
}

extern "C" void count_signal(int) {}

TEST(NestedDissectionOrdering, LeavesTheProgramsSignalHandlersAsTheyWere) {
  // METIS (GKlib) traps SIGTERM and SIGABRT while it orders, and puts the handlers back with
  // signal(): System V semantics, reset on delivery and without SA_RESTART. The ordering puts
  // them back exactly.
  struct sigaction handler {};
  handler.sa_handler = count_signal;
  sigemptyset(&handler.sa_mask);
  handler.sa_flags = SA_RESTART;
  struct sigaction before[2];
  const int signals[] = {SIGTERM, SIGABRT};
  for (int k = 0; k < 2; ++k) ASSERT_EQ(sigaction(signals[k], &handler, &before[k]), 0);
  Matrix path(300, 300);
  path.setIdentity();
  for (int i = 0; i + 1 < 300; ++i) path.coeffRef(i, i + 1) = path.coeffRef(i + 1, i) = -0.5;
  NestedDissectionOrdering::PermutationType permutation;
  NestedDissectionOrdering()(path, permutation);
  for (int k = 0; k < 2; ++k) {
    struct sigaction after {};
    ASSERT_EQ(sigaction(signals[k], &before[k], &after), 0);  // and back to the test's
    EXPECT_EQ(after.sa_handler, &count_signal) << "signal " << signals[k];
    EXPECT_EQ(after.sa_flags & (SA_RESTART | SA_RESETHAND), SA_RESTART) << "signal " << signals[k];
  }
  EXPECT_EQ(permutation.size(), 300);
}

}  // namespace
}  // namespace tissu
