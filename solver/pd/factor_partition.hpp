#pragma once
/// \file
/// Two independent halves of a sparse Cholesky factor, for triangular solves on two threads.
///
/// In the elimination tree of L (the parent of column j is the first row below the diagonal in
/// column j), the columns of two disjoint subtrees never touch each other's rows: a forward or
/// backward sweep over one subtree reads and writes only that subtree's rows and the rows of its
/// ancestors. Below the top separator (the chain of single-child columns from the root, which a
/// nested-dissection ordering numbers last), the tree falls apart into subtrees; dealt to two
/// halves of about equal work, they can be swept at once, the separator after them (forward) or
/// before them (backward) (George, Heath & Liu 1986; the subtree-to-subcube mapping of Gupta &
/// Kumar 1995, on two processors).

#include <array>
#include <vector>

namespace tissu {

/// Which columns of a factor each half sweeps, and where the separator rows start in each column.
struct FactorPartition {
  /// First column of the top separator: columns [separator_start, #columns) are the separator
  /// (#columns when there is none, as for a factor of several disconnected pieces).
  int separator_start = 0;
  /// ascending columns of each half; with the separator, every column once
  std::array<std::vector<int>, 2> half_columns;
  /// #columns, set for the half columns: the first entry of column j (an index into the factor's
  /// row and value arrays) whose row is in the separator; entries before it, from the first below
  /// the diagonal, are rows of j's own half.
  std::vector<int> separator_entry;
  std::vector<int> first_below_diagonal;  ///< #columns: first entry of column j with row > j
};

/// Partitions the columns of a lower-triangular factor of `columns` columns, in compressed
/// columns (`column_offsets` #columns+1, `rows` ascending within each column; the diagonal may be
/// stored or not). The halves' work (entries) is balanced greedily over the subtrees below the
/// top separator, heaviest first; the result depends on the factor only.
FactorPartition partition_factor(int columns, const int* column_offsets, const int* rows);

}  // namespace tissu
