#include "solver/pd/pd_iterative_solvers.hpp"

#include <cassert>

#include "solver/parallel.hpp"

namespace tissu {
namespace {

// (c_i + sum_j s_ij p_j) / a_i, the Jacobi / Gauss-Seidel value of particle i
inline Eigen::Vector3d local_solution(const PdSystem& system, const Eigen::VectorXd& c,
                                      const Eigen::VectorXd& p, int i) {
  Eigen::Vector3d sum = c.segment<3>(3 * i);
  for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
    sum += system.weights[e] * p.segment<3>(3 * system.neighbours[e]);
  }
  return sum / system.diagonal[i];
}

void prepare(const Eigen::VectorXd& p, PdIterativeState& state) {
  if (state.next.size() != p.size()) state.next.resize(p.size());
  if (state.previous.size() != p.size()) {
    state.previous = p;
    state.sweeps = 0;
    state.omega = 1.0;
  }
}

}  // namespace

void reset_pd_iterative_state(const Eigen::VectorXd& p, PdIterativeState& state) {
  state.next.resize(p.size());
  state.previous.resize(p.size());
  state.previous = p;
  state.omega = 1.0;
  state.sweeps = 0;
}

void pd_jacobi_sweep(const PdSystem& system, const Eigen::VectorXd& c, double relaxation,
                     Eigen::VectorXd& p, PdIterativeState& state) {
  prepare(p, state);
  const int particles = static_cast<int>(system.pinned.size());
  Eigen::VectorXd& next = state.next;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int i = 0; i < particles; ++i) {
    if (system.pinned[i]) {
      next.segment<3>(3 * i) = p.segment<3>(3 * i);
    } else {
      next.segment<3>(3 * i) =
          relaxation * local_solution(system, c, p, i) + (1.0 - relaxation) * p.segment<3>(3 * i);
    }
  }
  p.swap(next);
  ++state.sweeps;
}

void pd_chebyshev_sweep(const PdSystem& system, const Eigen::VectorXd& c, double relaxation,
                        double spectral_radius, int delay, Eigen::VectorXd& p,
                        PdIterativeState& state) {
  prepare(p, state);
  const int start = delay < 1 ? 1 : delay;
  const int k = state.sweeps;
  const double rho2 = spectral_radius * spectral_radius;
  double omega = 1.0;
  if (k == start) {
    omega = 2.0 / (2.0 - rho2);
  } else if (k > start) {
    omega = 4.0 / (4.0 - rho2 * state.omega);
  }
  const int particles = static_cast<int>(system.pinned.size());
  Eigen::VectorXd& next = state.next;
  const Eigen::VectorXd& previous = state.previous;
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int i = 0; i < particles; ++i) {
    const auto pi = p.segment<3>(3 * i);
    if (system.pinned[i]) {
      next.segment<3>(3 * i) = pi;
      continue;
    }
    const auto qi = previous.segment<3>(3 * i);
    next.segment<3>(3 * i) =
        omega * (relaxation * (local_solution(system, c, p, i) - pi) + pi - qi) + qi;
  }
  // previous <- p, p <- next, without copies
  state.previous.swap(p);
  p.swap(state.next);
  state.omega = omega;
  ++state.sweeps;
}

void pd_gauss_seidel_sweep(const PdSystem& system, const Eigen::VectorXd& c, Eigen::VectorXd& p) {
  for (const int i : system.free_particles) {
    p.segment<3>(3 * i) = local_solution(system, c, p, i);
  }
}

void pd_colored_gauss_seidel_sweep(const PdSystem& system, const Eigen::VectorXd& c,
                                   Eigen::VectorXd& p) {
  const int colors = static_cast<int>(system.free_color_offsets.size()) - 1;
  const int particles = static_cast<int>(system.free_color_order.size());
#pragma omp parallel if (particles >= min_parallel_items)
  for (int color = 0; color < colors; ++color) {
    const int begin = system.free_color_offsets[color];
    const int end = system.free_color_offsets[color + 1];
#pragma omp for schedule(static)
    for (int k = begin; k < end; ++k) {
      const int i = system.free_color_order[k];
      p.segment<3>(3 * i) = local_solution(system, c, p, i);
    }
  }
}

void pd_block_gauss_seidel_sweep(const PdSystem& system, const Eigen::VectorXd& c,
                                 Eigen::VectorXd& p) {
  const ParticleColoring& blocks = system.block_coloring;
  const int particles = static_cast<int>(system.free_particles.size());
#pragma omp parallel if (particles >= min_parallel_items)
  for (int color = 0; color < blocks.color_count(); ++color) {
#pragma omp for schedule(static)
    for (int k = blocks.color_offsets[color]; k < blocks.color_offsets[color + 1]; ++k) {
      const int block = blocks.order[k];
      for (int f = system.block_offsets[block]; f < system.block_offsets[block + 1]; ++f) {
        const int i = system.free_particles[f];
        p.segment<3>(3 * i) = local_solution(system, c, p, i);
      }
    }
  }
}

double pd_chebyshev_spectral_radius(const PdSystem& system,
                                    const ProjectiveDynamicsOptions& options) {
  if (options.chebyshev_spectral_radius > 0.0) return options.chebyshev_spectral_radius;
  return 1.0 - options.chebyshev_relaxation * (1.0 - system.jacobi_radius_bound);
}

void pd_iterative_solve(const PdSystem& system, const ProjectiveDynamicsOptions& options,
                        const Eigen::VectorXd& c, int sweeps, Eigen::VectorXd& p,
                        PdIterativeState& state) {
  assert(options.global_solver != PdGlobalSolver::direct);
  const double rho = pd_chebyshev_spectral_radius(system, options);
  for (int n = 0; n < sweeps; ++n) {
    switch (options.global_solver) {
      case PdGlobalSolver::jacobi:
        pd_jacobi_sweep(system, c, 1.0, p, state);
        break;
      case PdGlobalSolver::chebyshev:
        pd_chebyshev_sweep(system, c, options.chebyshev_relaxation, rho, options.chebyshev_delay, p,
                           state);
        break;
      case PdGlobalSolver::gauss_seidel:
        pd_gauss_seidel_sweep(system, c, p);
        break;
      case PdGlobalSolver::colored_gauss_seidel:
        pd_colored_gauss_seidel_sweep(system, c, p);
        break;
      case PdGlobalSolver::block_gauss_seidel:
        pd_block_gauss_seidel_sweep(system, c, p);
        break;
      case PdGlobalSolver::direct:
        break;
    }
  }
}

}  // namespace tissu
