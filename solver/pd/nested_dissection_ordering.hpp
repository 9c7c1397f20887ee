#pragma once
/// \file
/// A fill-reducing ordering for Eigen's sparse Cholesky factorisations by METIS's nested
/// dissection (Karypis & Kumar 1998, METIS_NodeND), which numbers each separator after the two
/// halves it separates: the factor's elimination tree then splits into independent subtrees that
/// can be solved in parallel (factor_partition.hpp).

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

namespace tissu {

/// Nested-dissection permutation of a symmetric matrix's graph, an Eigen ordering functor
/// (SimplicialLDLT<Matrix, Eigen::Lower, NestedDissectionOrdering>). Falls back on Eigen's AMD for
/// graphs METIS has no use for (fewer than 3 vertices, no edge) or refuses. Deterministic: METIS
/// runs with a fixed seed.
class NestedDissectionOrdering {
 public:
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

  /// `matrix` holds the whole symmetric pattern (Eigen passes both triangles); its values are
  /// ignored. Fills `permutation` as Eigen's orderings do: indices()[new] = old (the factorisation
  /// inverts it).
  void operator()(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& matrix,
                  PermutationType& permutation) const;
};

}  // namespace tissu
