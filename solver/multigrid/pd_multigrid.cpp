#include "solver/multigrid/pd_multigrid.hpp"

#include <algorithm>

#include "solver/multigrid/greedy_aggregation.hpp"
#include "solver/parallel.hpp"
#include "solver/pd/pd_direct_solver.hpp"

namespace tissu {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using FloatRowMatrix = Eigen::SparseMatrix<float, Eigen::RowMajor>;

// Chosen on the stiff hanging sheet (docs/benchmarks.md, "quasi-Newton's initial Hessian by
// multigrid" and "one sweep a side"): one cycle's error factor in the energy norm at 81 x 81
// particles is 0.46 with one sweep of omega 0.9, 0.32 with two (with two, omega 0.6 and 0.8 gave
// 0.42 and 0.35), but quasi-Newton takes about as many iterations with either (21.3 and 20.5 a
// step), and one sweep a side halves the products by A: 18 to 27 % off a frame.
constexpr int coarsest_nodes = 100;       // a level this small is solved exactly
constexpr int sweeps = 1;                 // damped Jacobi sweeps before and after the coarse level
constexpr double smoother_damping = 0.9;  // omega of the sweeps, where rho(D^-1 A) <= 2
constexpr double prolongator_damping = 4.0 / 3.0;  // omega rho(D^-1 A) of the smoothed prolongator

// row i of B - A X; inlined, so that the sums stay in registers
[[gnu::always_inline]] inline Eigen::Vector3d row_residual(const FloatRowMatrix& a,
                                                           const Eigen::Matrix3Xd& b,
                                                           const Eigen::Matrix3Xd& x, int i) {
  const int* columns = a.innerIndexPtr();
  const float* values = a.valuePtr();
  Eigen::Vector3d sum = b.col(i);
  for (int k = a.outerIndexPtr()[i]; k < a.outerIndexPtr()[i + 1]; ++k) {
    sum -= double(values[k]) * x.col(columns[k]);
  }
  return sum;
}

// Y = M X, or Y += M X when `accumulate`, column by column of the 3 x n blocks
void multiply(const FloatRowMatrix& m, const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& y,
              bool accumulate = false) {
  const int rows = static_cast<int>(m.rows());
  const int* offsets = m.outerIndexPtr();
  const int* columns = m.innerIndexPtr();
  const float* values = m.valuePtr();
#pragma omp parallel for schedule(static) if (rows >= min_parallel_items)
  for (int i = 0; i < rows; ++i) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k = offsets[i]; k < offsets[i + 1]; ++k) {
      sum += double(values[k]) * x.col(columns[k]);
    }
    if (accumulate) {
      y.col(i) += sum;
    } else {
      y.col(i) = sum;
    }
  }
}

// R = B - A X
void residual(const FloatRowMatrix& a, const Eigen::Matrix3Xd& b, const Eigen::Matrix3Xd& x,
              Eigen::Matrix3Xd& r) {
  const int rows = static_cast<int>(a.rows());
#pragma omp parallel for schedule(static) if (rows >= min_parallel_items)
  for (int i = 0; i < rows; ++i) r.col(i) = row_residual(a, b, x, i);
}

// one damped Jacobi sweep into another buffer, X_swept = X + S (B - A X), S = diag(omega / A_ii);
// from X = 0 (no `x`) it is X_swept = S B
void jacobi_sweep(const FloatRowMatrix& a, const Eigen::Matrix3Xd& b, const Eigen::VectorXd& scale,
                  const Eigen::Matrix3Xd* x, Eigen::Matrix3Xd& swept) {
  const int rows = static_cast<int>(a.rows());
#pragma omp parallel for schedule(static) if (rows >= min_parallel_items)
  for (int i = 0; i < rows; ++i) {
    swept.col(i) = x == nullptr ? Eigen::Vector3d(scale[i] * b.col(i))
                                : Eigen::Vector3d(x->col(i) + scale[i] * row_residual(a, b, *x, i));
  }
}

// the tentative prolongator: T(i, a) = 1 if node i is in aggregate a
RowMatrix tentative_prolongator(const std::vector<int>& aggregate, int aggregates) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(aggregate.size());
  for (int i = 0; i < static_cast<int>(aggregate.size()); ++i) {
    if (aggregate[i] >= 0) entries.emplace_back(i, aggregate[i], 1.0);
  }
  RowMatrix t(static_cast<Eigen::Index>(aggregate.size()), aggregates);
  t.setFromTriplets(entries.begin(), entries.end());
  return t;
}

// Gershgorin bound on the spectral radius of D^-1 A
double jacobi_radius_bound(const RowMatrix& a, const Eigen::VectorXd& diagonal) {
  double bound = 0.0;
  for (int i = 0; i < a.rows(); ++i) {
    double row_sum = 0.0;
    for (RowMatrix::InnerIterator entry(a, i); entry; ++entry) row_sum += std::abs(entry.value());
    bound = std::max(bound, row_sum / diagonal[i]);
  }
  return bound;
}

// The graph the aggregates are grown on, in compressed rows.
struct AggregationGraph {
  std::vector<int> offsets{0};  // #nodes+1
  std::vector<int> nodes;       // neighbours of each node, sorted, without the node itself
};

void append_row(std::vector<int>& row, AggregationGraph& graph) {
  std::sort(row.begin(), row.end());
  row.erase(std::unique(row.begin(), row.end()), row.end());
  graph.nodes.insert(graph.nodes.end(), row.begin(), row.end());
  graph.offsets.push_back(static_cast<int>(graph.nodes.size()));
}

// The free particles joined by structural or shear springs (the mesh's edges and quad diagonals):
// aggregates grown on it span one ring, about 3 x 3 particles on a grid. Grown on the PD matrix's
// graph, which the bending springs widen to two rings, they span 5 x 5, and a Jacobi sweep cannot
// smooth what so coarse a level misses (a cycle's error factor 0.73 on the stiff 81 x 81 sheet).
// A particle with bending springs only keeps them.
AggregationGraph nearest_neighbour_graph(const SpringModel& model, const PdSystem& system) {
  AggregationGraph graph;
  std::vector<int> row, bending_row;
  for (const int i : system.free_particles) {
    row.clear();
    bending_row.clear();
    for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
      const int j = system.free_index[system.neighbours[e]];
      if (j < 0 || j == system.free_index[i]) continue;
      const bool bending = model.kind[model.incidence.springs[e]] == SpringKind::bending;
      (bending ? bending_row : row).push_back(j);
    }
    append_row(row.empty() ? bending_row : row, graph);
  }
  return graph;
}

// The damped Jacobi sweep's omega / A_ii, with omega rho(D^-1 A) <= 2 smoother_damping < 2 by
// Gershgorin's bound `radius_bound` of rho(D^-1 A): the sweep converges, the cycle is definite.
Eigen::VectorXd jacobi_scale(const Eigen::VectorXd& diagonal, double radius_bound) {
  return (smoother_damping * 2.0 / std::max(radius_bound, 2.0)) * diagonal.cwiseInverse();
}

// Aggregates a and b are neighbours when some of their nodes are.
AggregationGraph quotient_graph(const AggregationGraph& fine, const std::vector<int>& aggregate,
                                int aggregates) {
  std::vector<std::vector<int>> rows(aggregates);
  for (int i = 0; i + 1 < static_cast<int>(fine.offsets.size()); ++i) {
    const int a = aggregate[i];
    if (a < 0) continue;
    for (int k = fine.offsets[i]; k < fine.offsets[i + 1]; ++k) {
      const int b = aggregate[fine.nodes[k]];
      if (b >= 0 && b != a) rows[a].push_back(b);
    }
  }
  AggregationGraph coarse;
  for (std::vector<int>& row : rows) append_row(row, coarse);
  return coarse;
}

// the level's Jacobi scale, from its operator A's own Gershgorin bound; returns the bound on
// rho(D^-1 A)
double set_jacobi_scale(PdMultigridLevel& level) {
  const Eigen::VectorXd diagonal = level.matrix.diagonal();
  const double radius_bound = jacobi_radius_bound(level.matrix, diagonal);
  level.jacobi_scale = jacobi_scale(diagonal, radius_bound);
  return radius_bound;
}

// the level's operator A, its Jacobi scale and the float copy the cycles read; returns the bound
// on rho(D^-1 A)
double set_operator(PdMultigridLevel& level, RowMatrix matrix) {
  level.matrix = std::move(matrix);
  level.cycle_matrix = level.matrix.cast<float>();
  return set_jacobi_scale(level);
}

// the position of each row's diagonal entry among a compressed matrix's values (every row has one)
std::vector<int> diagonal_positions(const RowMatrix& a) {
  std::vector<int> positions(a.rows());
  for (int i = 0; i < a.rows(); ++i) {
    const int* begin = a.innerIndexPtr() + a.outerIndexPtr()[i];
    const int* end = a.innerIndexPtr() + a.outerIndexPtr()[i + 1];
    positions[i] = static_cast<int>(std::lower_bound(begin, end, i) - a.innerIndexPtr());
  }
  return positions;
}

}  // namespace

bool PdMultigrid::prepare(const SpringModel& model, const PdSystem& system) {
  if (m_generation == system.generation && !m_levels.empty()) return true;
  m_generation = 0;
  m_levels.clear();
  m_levels.emplace_back();
  RowMatrix finest = pd_free_particle_matrix(system);
  if (!(finest.diagonal().array() > 0.0).all()) return false;
  double radius_bound = set_operator(m_levels[0], std::move(finest));
  AggregationGraph graph = nearest_neighbour_graph(model, system);
  for (int index = 0;; ++index) {
    PdMultigridLevel& fine = m_levels[index];
    const RowMatrix& a = fine.matrix;
    const int nodes = static_cast<int>(a.rows());
    const Eigen::VectorXd diagonal = a.diagonal();
    fine.base_matrix = a;
    if (index == 0) m_finest_diagonal = diagonal_positions(fine.base_matrix);
    fine.solution.setZero(3, nodes);
    fine.residual.setZero(3, nodes);
    fine.right_side.setZero(3, nodes);
    if (nodes <= coarsest_nodes) break;
    std::vector<int> aggregate;
    const int aggregates = greedy_aggregation(
        nodes,
        [&](int i, auto visit) {
          for (int k = graph.offsets[i]; k < graph.offsets[i + 1]; ++k) visit(graph.nodes[k]);
        },
        aggregate);
    if (aggregates == 0 || aggregates * 5 > nodes * 4) break;  // no longer coarsening
    graph = quotient_graph(graph, aggregate, aggregates);
    // P = (I - omega D^-1 A) T with omega = 4 / (3 rho(D^-1 A)) (Vanek et al. 1996, eq. 4.3)
    const double omega = prolongator_damping / radius_bound;
    const RowMatrix t = tentative_prolongator(aggregate, aggregates);
    const RowMatrix scaled_a = (omega * diagonal.cwiseInverse()).asDiagonal() * a;
    const RowMatrix smoothing = scaled_a * t;
    fine.prolongator = t - smoothing;
    fine.prolongator.prune(0.0);
    fine.restrictor = fine.prolongator.transpose();
    fine.cycle_prolongator = fine.prolongator.cast<float>();
    fine.cycle_restrictor = fine.restrictor.cast<float>();
    const RowMatrix a_p = a * fine.prolongator;
    RowMatrix coarse = fine.restrictor * a_p;
    coarse.prune(0.0);
    m_levels.emplace_back();
    radius_bound = set_operator(m_levels.back(), std::move(coarse));
  }
  m_extra = false;
  if (!factor_coarsest()) return false;
  m_generation = system.generation;
  return true;
}

bool PdMultigrid::factor_coarsest() {
  const Eigen::SparseMatrix<double> coarsest(m_levels.back().matrix);
  const bool same_pattern =
      m_coarsest && m_coarsest_pattern.outer.size() == std::size_t(coarsest.outerSize() + 1) &&
      std::equal(m_coarsest_pattern.outer.begin(), m_coarsest_pattern.outer.end(),
                 coarsest.outerIndexPtr()) &&
      m_coarsest_pattern.inner.size() == std::size_t(coarsest.nonZeros()) &&
      std::equal(m_coarsest_pattern.inner.begin(), m_coarsest_pattern.inner.end(),
                 coarsest.innerIndexPtr());
  if (!same_pattern) {  // ordering and elimination tree once per pattern, not per step
    m_coarsest = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>();
    m_coarsest->analyzePattern(coarsest);
    m_coarsest_pattern.outer.assign(coarsest.outerIndexPtr(),
                                    coarsest.outerIndexPtr() + coarsest.outerSize() + 1);
    m_coarsest_pattern.inner.assign(coarsest.innerIndexPtr(),
                                    coarsest.innerIndexPtr() + coarsest.nonZeros());
  }
  m_coarsest->factorize(coarsest);
  return m_coarsest->info() == Eigen::Success;
}

bool PdMultigrid::set_extra_diagonal(const Eigen::VectorXd& extra) {
  if (m_levels.empty() || (extra.size() == 0 && !m_extra)) return true;
  m_extra = extra.size() > 0;
  RowMatrix added;  // R D P at the level below, as the levels go down
  for (std::size_t index = 0; index < m_levels.size(); ++index) {
    PdMultigridLevel& level = m_levels[index];
    if (!m_extra) {
      set_operator(level, level.base_matrix);
    } else if (index == 0) {  // A + D changes A's diagonal only: in place, in both copies
      for (int i = 0; i < extra.size(); ++i) {
        const int k = m_finest_diagonal[i];
        level.matrix.valuePtr()[k] = level.base_matrix.valuePtr()[k] + extra[i];
        level.cycle_matrix.valuePtr()[k] = float(level.matrix.valuePtr()[k]);
      }
      set_jacobi_scale(level);
    } else {
      const PdMultigridLevel& fine = m_levels[index - 1];
      added = index == 1
                  ? RowMatrix(fine.restrictor * RowMatrix(extra.asDiagonal() * fine.prolongator))
                  : RowMatrix(fine.restrictor * RowMatrix(added * fine.prolongator));
      set_operator(level, level.base_matrix + added);
    }
  }
  return factor_coarsest();
}

void PdMultigrid::cycle(int index) {
  PdMultigridLevel& level = m_levels[index];
  if (index + 1 == static_cast<int>(m_levels.size())) {
    m_coarsest_right_side = level.right_side.transpose();  // the factor solves columns
    m_coarsest_solution = m_coarsest->solve(m_coarsest_right_side);
    level.solution = m_coarsest_solution.transpose();
    return;
  }
  // each sweep writes the residual's buffer, free until the restriction, then takes it back
  const auto sweep_again = [&] {
    jacobi_sweep(level.cycle_matrix, level.right_side, level.jacobi_scale, &level.solution,
                 level.residual);
    level.solution.swap(level.residual);
  };
  jacobi_sweep(level.cycle_matrix, level.right_side, level.jacobi_scale, nullptr, level.solution);
  for (int sweep = 1; sweep < sweeps; ++sweep) sweep_again();
  residual(level.cycle_matrix, level.right_side, level.solution, level.residual);
  PdMultigridLevel& coarse = m_levels[index + 1];
  multiply(level.cycle_restrictor, level.residual, coarse.right_side);
  cycle(index + 1);
  multiply(level.cycle_prolongator, coarse.solution, level.solution, true);  // X += P E
  for (int sweep = 0; sweep < sweeps; ++sweep) sweep_again();
}

bool PdMultigrid::apply(const SpringModel& model, const PdSystem& system, const Eigen::VectorXd& r,
                        Eigen::VectorXd& z) {
  if (!prepare(model, system)) return false;
  PdMultigridLevel& finest = m_levels[0];
  const int free_count = static_cast<int>(system.free_particles.size());
#pragma omp parallel for schedule(static) if (free_count >= min_parallel_items)
  for (int f = 0; f < free_count; ++f) {
    finest.right_side.col(f) = r.segment<3>(3 * system.free_particles[f]);
  }
  cycle(0);
  z.setZero(r.size());
#pragma omp parallel for schedule(static) if (free_count >= min_parallel_items)
  for (int f = 0; f < free_count; ++f) {
    z.segment<3>(3 * system.free_particles[f]) = finest.solution.col(f);
  }
  return true;
}

}  // namespace tissu
