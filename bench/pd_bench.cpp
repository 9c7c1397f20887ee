// Throughput of Projective Dynamics' global step: one sweep of each iterative global solver on
// n x n grids with structural, shear and bending springs, 1 and 2 threads, reported as spring
// updates per second (items_per_second: #S per sweep; each spring is read from both of its ends).
// Also the local step with the right-hand side assembly, per spring, and the cost of rebuilding the
// system and its colouring after a topology change. Results: docs/benchmarks.md.

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <utility>
#include <vector>

#include "solver/integrators/incremental_potential.hpp"
#include "solver/integrators/projective_dynamics.hpp"
#include "solver/multigrid/pd_multigrid.hpp"
#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_iterative_solvers.hpp"
#include "solver/pd/pd_system.hpp"

namespace tissu {
namespace {

/// n x n particles 1/(n-1) m apart in the z = 0 plane, 0.2 kg/m^2 lumped equally, springs along
/// the grid lines and across each quad (1000 N/m) and two apart (4 N/m), top row pinned.
SpringModel grid(int n, State& state) {
  SpringModel model;
  const double spacing = 1.0 / (n - 1);
  const auto id = [n](int column, int row) { return row * n + column; };
  state.x.resize(3 * n * n);
  state.v.setZero(3 * n * n);
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      state.x.segment<3>(3 * id(column, row)) << column * spacing, row * spacing, 0.0;
    }
  }
  model.mass.setConstant(n * n, 0.2 / (n * n));
  model.pinned.assign(n * n, 0);
  for (int column = 0; column < n; ++column) model.pinned[id(column, n - 1)] = 1;
  std::vector<std::pair<int, int>> pairs;
  std::vector<SpringKind> kinds;
  for (int row = 0; row < n; ++row) {
    for (int column = 0; column < n; ++column) {
      const auto add = [&](int column2, int row2, SpringKind kind) {
        if (column2 < 0 || column2 >= n || row2 >= n) return;
        pairs.emplace_back(id(column, row), id(column2, row2));
        kinds.push_back(kind);
      };
      add(column + 1, row, SpringKind::structural);
      add(column, row + 1, SpringKind::structural);
      add(column + 1, row + 1, SpringKind::shear);
      add(column - 1, row + 1, SpringKind::shear);
      add(column + 2, row, SpringKind::bending);
      add(column, row + 2, SpringKind::bending);
    }
  }
  const int springs = static_cast<int>(pairs.size());
  model.springs.resize(springs, 2);
  model.rest_length.resize(springs);
  model.stiffness.resize(springs);
  model.damping.setZero(springs);
  model.kind = kinds;
  for (int s = 0; s < springs; ++s) {
    model.springs.row(s) << pairs[s].first, pairs[s].second;
    model.rest_length[s] =
        (state.x.segment<3>(3 * pairs[s].first) - state.x.segment<3>(3 * pairs[s].second)).norm();
    model.stiffness[s] = kinds[s] == SpringKind::bending ? 4.0 : 1000.0;
  }
  model.triangles.resize(0, 3);
  finalize_model(model);
  return model;
}

constexpr double time_step_s = 1.0 / 60.0;

/// The grid of `side` particles a side and its PD system at time_step_s.
struct GridSystem {
  State state;
  SpringModel model;
  PdSystem system;
  explicit GridSystem(int side) : model(grid(side, state)) {
    update_pd_system(model, time_step_s, system);
  }
};

void BM_GlobalSweep(benchmark::State& bench) {
  const auto solver = static_cast<PdGlobalSolver>(bench.range(0));
  const int side = static_cast<int>(bench.range(1));
  omp_set_num_threads(static_cast<int>(bench.range(2)));
  GridSystem fixture(side);
  auto& [state, model, system] = fixture;
  // right-hand side of a falling step: M/h^2 (x + h^2 g) + J d at the rest shape
  Eigen::Matrix3Xd projections;
  pd_local_step(model, state.x, state.x, projections);
  Eigen::VectorXd y = state.x;
  for (int p = 0; p < model.particle_count(); ++p) y[3 * p + 2] -= 9.81 * time_step_s * time_step_s;
  Eigen::VectorXd rhs;
  pd_global_rhs(model, system, y, projections, rhs);
  ProjectiveDynamicsOptions options;
  options.global_solver = solver;
  Eigen::VectorXd p = state.x;
  PdIterativeState iterative;
  reset_pd_iterative_state(p, iterative);
  for (auto _ : bench) {
    pd_iterative_solve(system, options, rhs, 1, p, iterative);
    benchmark::DoNotOptimize(p.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(bench.iterations() * model.spring_count());
  bench.counters["particles"] = model.particle_count();
  bench.counters["springs"] = model.spring_count();
  bench.counters["colors"] = system.coloring.color_count();
  bench.counters["threads"] = static_cast<double>(bench.range(2));
}

void BM_LocalStepAndRhs(benchmark::State& bench) {
  const int side = static_cast<int>(bench.range(0));
  omp_set_num_threads(static_cast<int>(bench.range(1)));
  GridSystem fixture(side);
  auto& [state, model, system] = fixture;
  Eigen::Matrix3Xd projections;
  Eigen::VectorXd rhs;
  // once untimed, so that the buffers' first-touch page faults are not timed: a run reuses them
  pd_local_step(model, state.x, state.x, projections);
  pd_global_rhs(model, system, state.x, projections, rhs);
  for (auto _ : bench) {
    pd_local_step(model, state.x, state.x, projections);
    pd_global_rhs(model, system, state.x, projections, rhs);
    benchmark::DoNotOptimize(rhs.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(bench.iterations() * model.spring_count());
  bench.counters["threads"] = static_cast<double>(bench.range(1));
}

/// What a topology change costs the iterative PD solvers: rebuilding the global system from a
/// recompiled model, the greedy colouring of all particles included (update_pd_system), and the
/// colouring alone. Compare with one sweep (BM_GlobalSweep) to judge whether recolouring only the
/// changed neighbourhood would pay.
void BM_RebuildSystem(benchmark::State& bench) {
  State state;
  const SpringModel model = grid(static_cast<int>(bench.range(0)), state);
  PdSystem system;
  int rebuilds = 0;
  for (auto _ : bench) {
    // alternating h forces a rebuild into the same buffers, as a workspace after a recompile
    update_pd_system(model, time_step_s * (1 + ++rebuilds % 2), system);
    benchmark::DoNotOptimize(system.diagonal.data());
  }
  bench.counters["particles"] = model.particle_count();
}

void BM_ColorParticles(benchmark::State& bench) {
  GridSystem fixture(static_cast<int>(bench.range(0)));
  auto& [state, model, system] = fixture;
  for (auto _ : bench) {
    color_particles(system.neighbour_offsets, system.neighbours, system.coloring, system.scratch);
    benchmark::DoNotOptimize(system.coloring.color.data());
  }
  bench.counters["colors"] = system.coloring.color_count();
}

void sweep_arguments(benchmark::internal::Benchmark* b) {
  b->ArgNames({"solver", "side", "threads"});
  for (const PdGlobalSolver solver :
       {PdGlobalSolver::jacobi, PdGlobalSolver::chebyshev, PdGlobalSolver::gauss_seidel,
        PdGlobalSolver::colored_gauss_seidel, PdGlobalSolver::block_gauss_seidel}) {
    for (int side : {128, 256, 512, 1024}) {
      for (int threads : {1, 2}) b->Args({static_cast<int>(solver), side, threads});
    }
  }
}

/// Does single precision pay? The Jacobi sweep of PdSystem, written once for a Scalar type over
/// copies of its CSR rows, positions and right-hand side in that type (ids stay 4-byte ints).
/// Per spring end a sweep reads 4 + sizeof(Scalar) bytes of row, so float cuts 12 to 8 bytes.
template <typename Scalar>
void BM_JacobiSweepPrecision(benchmark::State& bench) {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  const int side = static_cast<int>(bench.range(0));
  omp_set_num_threads(static_cast<int>(bench.range(1)));
  GridSystem fixture(side);
  auto& [state, model, system] = fixture;
  const std::vector<int>& offsets = system.neighbour_offsets;
  const std::vector<int>& neighbours = system.neighbours;
  const std::vector<Scalar> weights(system.weights.begin(), system.weights.end());
  const Vector diagonal = system.diagonal.cast<Scalar>();
  // every row swept (pins ignored: this measures the kernel), with c_i = a_i x_i - sum s_ij x_j
  // so that the grid is the fixed point and the values stay bounded however long it runs
  Vector p = state.x.cast<Scalar>();
  Vector c(p.size());
  for (int i = 0; i < model.particle_count(); ++i) {
    Eigen::Matrix<Scalar, 3, 1> sum = diagonal[i] * p.template segment<3>(3 * i);
    for (int e = offsets[i]; e < offsets[i + 1]; ++e) {
      sum -= weights[e] * p.template segment<3>(3 * neighbours[e]);
    }
    c.template segment<3>(3 * i) = sum;
  }
  Vector next(p.size());
  const int particles = model.particle_count();
  for (auto _ : bench) {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < particles; ++i) {
      Eigen::Matrix<Scalar, 3, 1> sum = c.template segment<3>(3 * i);
      for (int e = offsets[i]; e < offsets[i + 1]; ++e) {
        sum += weights[e] * p.template segment<3>(3 * neighbours[e]);
      }
      next.template segment<3>(3 * i) = sum / diagonal[i];
    }
    p.swap(next);
    benchmark::DoNotOptimize(p.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(bench.iterations() * model.spring_count());
  bench.counters["bytes_per_scalar"] = sizeof(Scalar);
}

/// One solve with the prefactorised PD matrix (nested dissection, as a settled factor is), in
/// double (PD direct's global step) or float (the minimisers' preconditioner), one thread.
template <SolvePrecision precision>
void BM_DirectSolve(benchmark::State& bench) {
  const GridSystem grid_system(static_cast<int>(bench.range(0)));
  omp_set_num_threads(1);
  PdDirectSolver direct;
  direct.set_precision(precision);
  const Eigen::VectorXd c =
      grid_system.system.diagonal.replicate<3, 1>().reshaped<Eigen::RowMajor>().cwiseProduct(
          grid_system.state.x);
  Eigen::VectorXd p = grid_system.state.x;
  while (!direct.nested_dissection()) direct.solve(grid_system.system, c, p);
  for (auto _ : bench) {
    direct.solve(grid_system.system, c, p);
    benchmark::DoNotOptimize(p.data());
  }
  bench.counters["particles"] = grid_system.model.particle_count();
}

/// One smoothed-aggregation V-cycle on the same PD matrix (the other initial Hessian of
/// quasi-Newton), one thread: the hierarchy is built before the timing.
void BM_MultigridCycle(benchmark::State& bench) {
  const GridSystem grid_system(static_cast<int>(bench.range(0)));
  omp_set_num_threads(1);
  PdMultigrid multigrid;
  const Eigen::VectorXd c =
      grid_system.system.diagonal.replicate<3, 1>().reshaped<Eigen::RowMajor>().cwiseProduct(
          grid_system.state.x);
  Eigen::VectorXd p = grid_system.state.x;
  multigrid.prepare(grid_system.model, grid_system.system);
  for (auto _ : bench) {
    multigrid.apply(grid_system.model, grid_system.system, c, p);
    benchmark::DoNotOptimize(p.data());
  }
  bench.counters["particles"] = grid_system.model.particle_count();
  bench.counters["levels"] = multigrid.level_count();
}

// One evaluation of backward Euler's incremental potential and its gradient at a perturbed
// iterate, what every quasi-Newton and Newton iteration (and line search trial) pays
void BM_StepPotentialGradient(benchmark::State& bench) {
  GridSystem grid_system(static_cast<int>(bench.range(0)));
  auto& [state, model, system] = grid_system;
  omp_set_num_threads(1);
  model.damping.setConstant(model.spring_count(), 0.01);  // (N s/m) the viscous terms too
  Eigen::VectorXd inertial = state.x, x = state.x;
  for (int p = 0; p < model.particle_count(); ++p) {
    inertial[3 * p + 2] -= 9.81 * time_step_s * time_step_s;
    x[3 * p + 2] -= 0.01 * std::sin(7.0 * state.x[3 * p]) * std::cos(5.0 * state.x[3 * p + 1]);
  }
  StepPotential potential;
  potential.time_step_s = time_step_s;
  potential.start_x = &state.x;
  potential.inertial = &inertial;
  potential.air_damping = 0.1;
  StepPotentialWorkspace workspace;
  prepare_step_potential(model, potential, workspace);
  Eigen::VectorXd gradient;
  for (auto _ : bench) {
    benchmark::DoNotOptimize(evaluate_step_potential(model, potential, x, workspace, &gradient));
  }
  bench.counters["springs"] = model.spring_count();
  bench.counters["s_per_spring"] =
      benchmark::Counter(model.spring_count(), benchmark::Counter::kIsIterationInvariantRate |
                                                   benchmark::Counter::kInvert);
}

void side_arguments(benchmark::internal::Benchmark* b) {
  b->ArgName("side");
  for (int side : {128, 256, 512, 1024}) b->Arg(side);
}

void local_arguments(benchmark::internal::Benchmark* b) {
  b->ArgNames({"side", "threads"});
  for (int side : {128, 256, 512, 1024}) {
    for (int threads : {1, 2}) b->Args({side, threads});
  }
}

BENCHMARK(BM_GlobalSweep)->Apply(sweep_arguments)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RebuildSystem)->Apply(side_arguments)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColorParticles)->Apply(side_arguments)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JacobiSweepPrecision<double>)
    ->Apply(local_arguments)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_JacobiSweepPrecision<float>)
    ->Apply(local_arguments)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_DirectSolve<SolvePrecision::exact>)
    ->ArgName("side")
    ->Arg(81)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DirectSolve<SolvePrecision::single>)
    ->ArgName("side")
    ->Arg(81)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MultigridCycle)
    ->ArgName("side")
    ->Arg(81)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepPotentialGradient)
    ->ArgName("side")
    ->Arg(81)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LocalStepAndRhs)->Apply(local_arguments)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace tissu

BENCHMARK_MAIN();
