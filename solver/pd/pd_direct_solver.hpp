#pragma once
/// \file
/// Direct solve of Projective Dynamics' global step by a sparse Cholesky factorisation that is
/// computed once and reused while the system stays the same (Liu et al. 2013; Bouaziz et al. 2014:
/// the system matrix M/h^2 + L is constant, so its prefactorisation makes each global step two
/// triangular solves).

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "solver/pd/factor_partition.hpp"
#include "solver/pd/pd_system.hpp"

namespace tissu {

/// Arithmetic of PdDirectSolver's triangular sweeps.
enum class SolvePrecision {
  exact,   ///< double: the solve of Projective Dynamics' global step
  single,  ///< float factor and sweeps, about 1e-6 relative: a preconditioner's solve
};

/// The free-particle matrix A_ff (#F x #F, kg/s^2) of the global step, rows and columns in
/// system.free_particles order: A_ii = a_i, A_ij = -sum of the s_ij of springs joining free i and
/// j; pinned neighbours go to the right-hand side.
Eigen::SparseMatrix<double> pd_free_particle_matrix(const PdSystem& system);

/// Sparse LDL^T (Eigen SimplicialLDLT) of pd_free_particle_matrix(), symmetrically permuted by a
/// fill-reducing ordering chosen by how long the factor lives:
/// - a new system is ordered by approximate minimum degree (Eigen's AMD), the cheaper to compute;
/// - once that factor has served solves_before_nested_dissection solves, the system has settled
///   (no remeshing) and it is factorised again under METIS's nested dissection, whose tree splits
///   below its top separator into two halves of about equal work (factor_partition.hpp): the
///   triangular solves then sweep the two halves on two OpenMP threads when there are two.
/// AMD's tree is too lopsided to split. Both choices count solves, never threads, and the sweeps
/// keep one order of operations: the same bits for any number of threads. Refactorised when the
/// system's generation changes (update_pd_system() rebuilt it for a new model or time step).
/// With SolvePrecision::single the sweeps run in float on a float copy of the factor, x, y and z
/// padded to four lanes: about 1e-6 relative error, for the minimisers' preconditioner (the
/// factorisation itself stays double). Copying gives an unfactorised solver (Eigen's factorisations
/// are not copyable); it factorises again on first use.
class PdDirectSolver {
 public:
  PdDirectSolver() = default;
  PdDirectSolver(const PdDirectSolver& other) : m_precision(other.m_precision) {}
  PdDirectSolver& operator=(const PdDirectSolver& other) {
    m_precision = other.m_precision;
    m_ldlt.reset();
    m_generation = 0;
    m_nested_dissection = false;
    m_solves_on_factor = 0;
    return *this;
  }
  PdDirectSolver(PdDirectSolver&&) noexcept = default;
  PdDirectSolver& operator=(PdDirectSolver&&) noexcept = default;
  ~PdDirectSolver() = default;

  /// Factorises A_ff unless it is already factorised for this system. False if the factorisation
  /// failed (A_ff not positive definite: a free particle without mass).
  bool factorize(const PdSystem& system);

  /// Solves A_ff p_f = c_f + sum over pinned neighbours j of s_ij p_j for the free particles of p
  /// (3#P, m), pinned entries of p read, not written; c is 3#P (kg m/s^2). Factorises first if
  /// needed. False if the factorisation failed (p unchanged).
  bool solve(const PdSystem& system, const Eigen::VectorXd& c, Eigen::VectorXd& p);

  /// Sets the sweeps' arithmetic; a change factorises again at the next solve.
  void set_precision(SolvePrecision precision) {
    if (precision != m_precision) m_generation = 0;
    m_precision = precision;
  }

  /// Number of factorisations done by this object, for tests and benchmarks.
  int factorization_count() const { return m_factorizations; }
  /// Whether the current factor is ordered by nested dissection (else by minimum degree).
  bool nested_dissection() const { return m_nested_dissection; }

  /// Solves a factor serves before it is redone under nested dissection. At 81 x 81 particles
  /// METIS's ordering makes a factorisation about 17 ms slower (49 against 32 ms) and the
  /// two-thread solve saves about 0.4 ms per solve; the adaptive curtain refactors every 20 to 40
  /// solves, where nested dissection cost 14 to 17 % of its run (docs/benchmarks.md).
  static constexpr int solves_before_nested_dissection = 100;

 private:
  using Matrix = Eigen::SparseMatrix<double>;
  /// of the permuted matrix P A P^T, which this class orders itself
  using Factorization = Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::NaturalOrdering<int>>;
  std::unique_ptr<Factorization> m_ldlt;
  Eigen::VectorXi m_permutation;  ///< #F row of A -> row of P A P^T
  bool m_nested_dissection = false;
  int m_solves_on_factor = 0;      ///< solves since the last factorisation
  FactorPartition m_partition;     ///< the factor's halves and separator
  std::uint64_t m_generation = 0;  ///< system generation of the factorisation, 0 = none
  int m_factorizations = 0;
  Eigen::VectorXd m_inverse_d;  ///< #F 1 / D of the LDL^T factorisation (s^2/kg)
  Eigen::Matrix3Xd m_solution;  ///< 3 x #F right-hand side, then solution, in permuted order (m)
  /// 3 x #separator per half: what each half's forward sweep subtracts from the separator rows
  std::array<Eigen::Matrix3Xd, 2> m_separator_updates;
  SolvePrecision m_precision = SolvePrecision::exact;
  /// single precision: the factor's values, 1 / D, the solution padded to 4 rows, the updates
  std::vector<float> m_values_single;
  Eigen::VectorXf m_inverse_d_single;
  Eigen::Matrix4Xf m_solution_single;
  std::array<Eigen::Matrix4Xf, 2> m_separator_updates_single;

  template <class Scalar, int Rows>
  void sweep(const Scalar* values, const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& inverse_d,
             Eigen::Matrix<Scalar, Rows, Eigen::Dynamic>& solution,
             std::array<Eigen::Matrix<Scalar, Rows, Eigen::Dynamic>, 2>& separator_updates) const;
};

}  // namespace tissu
