#pragma once
/// \file
/// A smoothed-aggregation multigrid V-cycle for the Projective Dynamics matrix A_ff = M/h^2 + L on
/// the free particles (pd_system.hpp): the same scalar matrix for x, y and z, so one hierarchy
/// serves the three coordinates, and a cycle costs a few products by A_ff, linear in the particle
/// count where the factor's triangular sweeps grow with its fill. Its near-kernel is the constant
/// vector (L's), which the aggregates' piecewise-constant vectors reproduce; the prolongator is
/// smoothed by one damped Jacobi step so the coarse levels approximate it well (Vanek, Mandel &
/// Brezina 1996, "Algebraic multigrid by smoothed aggregation for second and fourth order elliptic
/// problems"). Meant as an approximate inverse: the initial Hessian of quasi-Newton (Liu, Bouaziz
/// & Kavan 2017 use the factorised PD matrix there). On the stiff sheet a cycle divides the error
/// by about 2 at any size and costs 0.33, 0.79 and 3.3 ms at 81^2, 128^2 and 256^2 particles on
/// one thread, where the factor's float solve takes 1.2, 3.7 and 19 ms (docs/benchmarks.md,
/// "quasi-Newton's initial Hessian by multigrid" and "one sweep a side").

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <vector>

#include "solver/pd/pd_system.hpp"

namespace tissu {

/// One level of the hierarchy: its operator and the maps to and from the next level.
struct PdMultigridLevel {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;       ///< n x n (kg/s^2), with the extra
  Eigen::SparseMatrix<double, Eigen::RowMajor> base_matrix;  ///< n x n, without (kg/s^2)
  Eigen::VectorXd jacobi_scale;                              ///< n: omega / A_ii (s^2/kg)
  Eigen::SparseMatrix<double, Eigen::RowMajor> prolongator;  ///< n x n_c, smoothed
  Eigen::SparseMatrix<double, Eigen::RowMajor> restrictor;   ///< n_c x n, its transpose
  Eigen::Matrix3Xd solution, residual, right_side;           ///< 3 x n scratch (x, y, z)
  /// what the cycle reads: the operator, the prolongator and the restrictor in float, 8 bytes an
  /// entry instead of 12 (an approximate inverse does not need the last digits)
  Eigen::SparseMatrix<float, Eigen::RowMajor> cycle_matrix, cycle_prolongator, cycle_restrictor;
};

/// The V-cycle: `sweeps` damped Jacobi sweeps, the residual restricted, the next level's cycle
/// prolongated back, `sweeps` sweeps again; the coarsest level solved by LDL^T. The same sweeps
/// before and after make the cycle a symmetric operator, positive definite since the damped
/// Jacobi sweep converges on A_ff (its Gershgorin bound is under 2 / omega): fit for L-BFGS's
/// initial inverse Hessian and for the conjugate gradient. Rebuilt when the system's generation
/// changes (a new model or time step). The same bits on any number of OpenMP threads.
class PdMultigrid {
 public:
  /// Builds the hierarchy for `system` (of `model`) unless it was built for this generation. False
  /// if A_ff is not positive definite (a free particle without mass or springs).
  bool prepare(const SpringModel& model, const PdSystem& system);

  /// Adds diag(extra) (#F, kg/s^2, >= 0, by free particle) to A_ff for the cycles that follow,
  /// until the next call or the next rebuild; an empty `extra` takes it off. The aggregates and
  /// prolongators stay (they are A_ff's); each level's operator is made again through them
  /// (A_c = R (A + D) P) with its Jacobi scale (from its own Gershgorin bound), and the coarsest
  /// factor. For stiffness that changes from step to step (friction in the step,
  /// contact_planes.hpp), so it is made cheap: the finest operator's diagonal is changed in place,
  /// and the coarsest factor keeps its ordering while its pattern holds (on the drape, 38 to 16 ms
  /// of a 0.7 s run). Call after prepare(). False if the coarsest factor fails.
  bool set_extra_diagonal(const Eigen::VectorXd& extra);

  /// z ~ A_ff^-1 r on the free particles by one V-cycle (r, z: 3#P; z's pinned entries set to 0,
  /// r's ignored). Prepares first if needed; false if that fails (z unchanged).
  bool apply(const SpringModel& model, const PdSystem& system, const Eigen::VectorXd& r,
             Eigen::VectorXd& z);

  int level_count() const { return static_cast<int>(m_levels.size()); }
  int node_count(int level) const { return static_cast<int>(m_levels[level].matrix.rows()); }

 private:
  void cycle(int level);
  bool factor_coarsest();
  std::uint64_t m_generation = 0;
  bool m_extra = false;  ///< an extra diagonal is on the levels' operators
  std::vector<PdMultigridLevel> m_levels;
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> m_coarsest;
  struct Pattern {
    std::vector<int> outer, inner;
  } m_coarsest_pattern;  ///< the pattern m_coarsest was analysed for (column-major)
  Eigen::Matrix<double, Eigen::Dynamic, 3> m_coarsest_right_side, m_coarsest_solution;
  std::vector<int> m_finest_diagonal;  ///< where each row's diagonal is among the finest values
};

}  // namespace tissu
