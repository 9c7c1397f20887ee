#include "solver/pd/pd_direct_solver.hpp"

#include <vector>

#include "solver/parallel.hpp"

namespace tissu {

bool PdDirectSolver::factorize(const PdSystem& system) {
  if (m_ldlt && m_generation == system.generation) return true;
  const int free_count = static_cast<int>(system.free_particles.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(system.neighbours.size() + system.free_particles.size());
  for (int row = 0; row < free_count; ++row) {
    const int i = system.free_particles[row];
    entries.emplace_back(row, row, system.diagonal[i]);
    for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
      const int column = system.free_index[system.neighbours[e]];
      if (column >= 0) entries.emplace_back(row, column, -system.weights[e]);
    }
  }
  Matrix matrix(free_count, free_count);
  matrix.setFromTriplets(entries.begin(), entries.end());
  if (!m_ldlt) m_ldlt = std::make_unique<Eigen::SimplicialLDLT<Matrix>>();
  m_ldlt->compute(matrix);
  ++m_factorizations;
  if (m_ldlt->info() != Eigen::Success) {
    m_generation = 0;
    return false;
  }
  m_generation = system.generation;
  m_inverse_d = m_ldlt->vectorD().cwiseInverse();  // vectorD() returns a copy: keep it
  m_rhs.resize(free_count, 3);
  m_solution.resize(free_count, 3);
  return true;
}

bool PdDirectSolver::solve(const PdSystem& system, const Eigen::VectorXd& c, Eigen::VectorXd& p) {
  if (!factorize(system)) return false;
  const int free_count = static_cast<int>(system.free_particles.size());
#pragma omp parallel for schedule(static) if (free_count >= min_parallel_items)
  for (int row = 0; row < free_count; ++row) {
    const int i = system.free_particles[row];
    Eigen::Vector3d b = c.segment<3>(3 * i);
    for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
      const int j = system.neighbours[e];
      if (system.pinned[j]) b += system.weights[e] * p.segment<3>(3 * j);
    }
    m_rhs.row(row) = b.transpose();
  }
  // x = P^-1 U^-1 D^-1 L^-1 P b, step by step into the kept buffers (Eigen's solve() allocates)
  const Eigen::SimplicialLDLT<Matrix>& ldlt = *m_ldlt;
  m_solution.noalias() = ldlt.permutationP() * m_rhs;
  ldlt.matrixL().solveInPlace(m_solution);
  m_solution.array().colwise() *= m_inverse_d.array();
  ldlt.matrixU().solveInPlace(m_solution);
  m_rhs.noalias() = ldlt.permutationPinv() * m_solution;
  m_solution.swap(m_rhs);
#pragma omp parallel for schedule(static) if (free_count >= min_parallel_items)
  for (int row = 0; row < free_count; ++row) {
    p.segment<3>(3 * system.free_particles[row]) = m_solution.row(row).transpose();
  }
  return true;
}

}  // namespace tissu
