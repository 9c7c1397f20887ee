// Every iterative solver of the PD global step converges to the direct (LDL^T) solution of the
// same linear system, on random spring networks and on a cloth grid.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "solver/pd/pd_direct_solver.hpp"
#include "solver/pd/pd_iterative_solvers.hpp"
#include "solver/pd/pd_system.hpp"
#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

const PdGlobalSolver iterative_solvers[] = {
    PdGlobalSolver::jacobi, PdGlobalSolver::chebyshev, PdGlobalSolver::gauss_seidel,
    PdGlobalSolver::colored_gauss_seidel, PdGlobalSolver::block_gauss_seidel};

struct LinearProblem {
  SpringModel model;
  PdSystem system;
  Eigen::VectorXd rhs;    // 3#P c
  Eigen::VectorXd start;  // 3#P initial iterate, pinned entries prescribed
};

// random right-hand side and start around the model's positions, a few particles pinned
LinearProblem make_problem(SpringModel model, const State& state, double h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  LinearProblem problem;
  for (int p = 0; p < model.particle_count(); p += 7) model.pinned[p] = 1;
  finalize_model(model);
  problem.model = std::move(model);
  update_pd_system(problem.model, h, problem.system);
  const Eigen::Index n = state.x.size();
  problem.start = state.x;
  for (Eigen::Index i = 0; i < n; ++i) problem.start[i] += 0.1 * unit(rng);
  // c = A x_target + noise, so that the solution is of the size of the positions
  problem.rhs.resize(n);
  for (int p = 0; p < problem.model.particle_count(); ++p) {
    problem.rhs.segment<3>(3 * p) = problem.system.inertia[p] * state.x.segment<3>(3 * p);
    for (int k = 0; k < 3; ++k) problem.rhs[3 * p + k] += 10.0 * unit(rng);
  }
  return problem;
}

Eigen::VectorXd direct_solution(const LinearProblem& problem) {
  PdDirectSolver direct;
  Eigen::VectorXd p = problem.start;
  EXPECT_TRUE(direct.solve(problem.system, problem.rhs, p));
  return p;
}

// sweeps until the iterate stops moving (or a cap), the fixed point of the iteration
Eigen::VectorXd iterate(const LinearProblem& problem, PdGlobalSolver solver, int max_sweeps) {
  ProjectiveDynamicsOptions options;
  options.global_solver = solver;
  Eigen::VectorXd p = problem.start;
  PdIterativeState state;
  reset_pd_iterative_state(p, state);
  for (int n = 0; n < max_sweeps; n += 10) {
    const Eigen::VectorXd before = p;
    pd_iterative_solve(problem.system, options, problem.rhs, 10, p, state);
    if ((p - before).lpNorm<Eigen::Infinity>() < 1e-15) break;
  }
  return p;
}

void expect_converges_to_direct(const LinearProblem& problem, int max_sweeps) {
  const Eigen::VectorXd exact = direct_solution(problem);
  const double scale = exact.lpNorm<Eigen::Infinity>();
  for (const PdGlobalSolver solver : iterative_solvers) {
    const Eigen::VectorXd p = iterate(problem, solver, max_sweeps);
    EXPECT_LT((p - exact).lpNorm<Eigen::Infinity>(), 1e-10 * scale) << to_string(solver);
    // pinned particles are not touched
    for (int i = 0; i < problem.model.particle_count(); ++i) {
      if (problem.model.pinned[i]) {
        EXPECT_EQ(Eigen::Vector3d(p.segment<3>(3 * i)),
                  Eigen::Vector3d(problem.start.segment<3>(3 * i)));
      }
    }
  }
}

TEST(PdGlobalSolvers, ConvergeToTheDirectSolveOnRandomSpringNetworks) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    State state;
    SpringModel model = test::random_model(30 + 5 * static_cast<int>(seed),
                                           150 + 20 * static_cast<int>(seed), 0, seed, state);
    SCOPED_TRACE(seed);
    expect_converges_to_direct(make_problem(std::move(model), state, 0.01, seed), 20000);
  }
}

TEST(PdGlobalSolvers, ConvergeToTheDirectSolveOnAClothGrid) {
  // 12 x 10 grid, structural + shear + bending springs, 30 steps per second: Jacobi's radius
  // bound is 2400 / (2400 + 0.002 * 30^2) = 0.9993
  State state;
  SpringModel model = test::grid_model(12, 10, 0.05, 0.002, 200.0, 0.0, state);
  const LinearProblem problem = make_problem(std::move(model), state, 1.0 / 30.0, 3);
  EXPECT_GT(problem.system.jacobi_radius_bound, 0.999);
  expect_converges_to_direct(problem, 200000);
}

TEST(PdGlobalSolvers, ChebyshevAndGaussSeidelBeatJacobiAndBlocksCostNoConvergence) {
  // stiff cloth at 30 steps per second held by two corners: slow smooth modes, Jacobi's radius
  // close to 1, where Wang 2015's acceleration pays
  State state;
  SpringModel model = test::grid_model(16, 16, 0.05, 0.002, 200.0, 0.0, state);
  model.pinned[0] = 1;
  model.pinned[15] = 1;
  finalize_model(model);
  LinearProblem problem;
  problem.model = model;
  update_pd_system(problem.model, 1.0 / 30.0, problem.system);
  problem.start = state.x;
  problem.rhs = Eigen::VectorXd::Zero(state.x.size());
  for (int p = 0; p < model.particle_count(); ++p) {
    problem.rhs.segment<3>(3 * p) = problem.system.inertia[p] * Eigen::Vector3d(0.0, 0.0, -1.0);
  }
  const Eigen::VectorXd exact = direct_solution(problem);
  const auto error_after = [&](PdGlobalSolver solver, int sweeps) {
    ProjectiveDynamicsOptions options;
    options.global_solver = solver;
    options.chebyshev_spectral_radius = 0.0;  // Gershgorin's bound: right for a linear solve
    Eigen::VectorXd p = problem.start;
    PdIterativeState state;
    reset_pd_iterative_state(p, state);
    pd_iterative_solve(problem.system, options, problem.rhs, sweeps, p, state);
    return (p - exact).lpNorm<Eigen::Infinity>();
  };
  EXPECT_LT(error_after(PdGlobalSolver::chebyshev, 100),
            0.1 * error_after(PdGlobalSolver::jacobi, 100));
  EXPECT_LT(error_after(PdGlobalSolver::gauss_seidel, 100),
            error_after(PdGlobalSolver::jacobi, 100));
  // block Gauss-Seidel (4 blocks of 4 rows here) loses nothing against the sequential order:
  // after 100 sweeps its error is within 10 % of Gauss-Seidel's (0.257 against 0.258 m here;
  // the particle-coloured sweep gives 0.250 m and Jacobi 0.346 m)
  const double block_m = error_after(PdGlobalSolver::block_gauss_seidel, 100);
  EXPECT_NEAR(block_m / error_after(PdGlobalSolver::gauss_seidel, 100), 1.0, 0.1);
  EXPECT_LT(block_m, error_after(PdGlobalSolver::jacobi, 100));
}

TEST(PdGlobalSolvers, IdenticalForOneAndTwoThreads) {
  // 30 x 30 particles: above min_parallel_items, so the loops do run on two threads
  State state;
  SpringModel model = test::grid_model(30, 30, 0.05, 0.002, 200.0, 0.0, state);
  const LinearProblem problem = make_problem(std::move(model), state, 1.0 / 100.0, 9);
  for (const PdGlobalSolver solver : iterative_solvers) {
    Eigen::VectorXd results[2];
    for (int threads = 1; threads <= 2; ++threads) {
      const test::ScopedThreadCount count(threads);
      ProjectiveDynamicsOptions options;
      options.global_solver = solver;
      Eigen::VectorXd p = problem.start;
      PdIterativeState state;
      reset_pd_iterative_state(p, state);
      pd_iterative_solve(problem.system, options, problem.rhs, 25, p, state);
      results[threads - 1] = p;
    }
    EXPECT_TRUE((results[0].array() == results[1].array()).all()) << to_string(solver);
    EXPECT_NE(results[0], problem.start) << to_string(solver);
  }
}

// the direct solve's residual: a_i p_i - sum_j s_ij p_j - c_i over the free particles (N)
double direct_residual_n(const LinearProblem& problem, const Eigen::VectorXd& p) {
  const PdSystem& system = problem.system;
  double largest_n = 0.0;
  for (const int i : system.free_particles) {
    Eigen::Vector3d residual =
        system.diagonal[i] * p.segment<3>(3 * i) - problem.rhs.segment<3>(3 * i);
    for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
      residual -= system.weights[e] * p.segment<3>(3 * system.neighbours[e]);
    }
    largest_n = std::max(largest_n, residual.lpNorm<Eigen::Infinity>());
  }
  return largest_n;
}

// the factor's two halves are swept on two threads when there are two: the same bits as one
TEST(PdDirectSolver, SolvesExactlyWithTheSameBitsOnOneAndTwoThreads) {
  State state;
  const LinearProblem problem =
      make_problem(test::grid_model(30, 30, 0.02, 0.001, 3000.0, 0.0, state), state, 1.0 / 30.0, 3);
  std::array<Eigen::VectorXd, 2> results;
  for (int threads = 1; threads <= 2; ++threads) {
    const test::ScopedThreadCount count(threads);
    results[threads - 1] = direct_solution(problem);
  }
  EXPECT_TRUE((results[0].array() == results[1].array()).all());
  const double scale_n = problem.rhs.lpNorm<Eigen::Infinity>();
  EXPECT_LT(direct_residual_n(problem, results[0]), 1e-9 * scale_n);
  for (int i = 0; i < problem.model.particle_count(); ++i) {  // pinned ones untouched
    if (problem.model.pinned[i]) {
      EXPECT_EQ(results[0].segment<3>(3 * i), problem.start.segment<3>(3 * i));
    }
  }
}

// a new factor is ordered by minimum degree; one that has served enough solves is redone under
// nested dissection, which gives the same solution and splits the solve on two threads, still
// with the same bits as one thread
TEST(PdDirectSolver, ASettledFactorIsReorderedByNestedDissection) {
  State state;
  const LinearProblem problem =
      make_problem(test::grid_model(30, 30, 0.02, 0.001, 3000.0, 0.0, state), state, 1.0 / 30.0, 5);
  PdDirectSolver direct;
  const auto solve = [&] {
    Eigen::VectorXd p = problem.start;
    EXPECT_TRUE(direct.solve(problem.system, problem.rhs, p));
    return p;
  };
  const Eigen::VectorXd by_minimum_degree = solve();
  for (int k = 1; k < PdDirectSolver::solves_before_nested_dissection; ++k) solve();
  EXPECT_FALSE(direct.nested_dissection());
  EXPECT_EQ(direct.factorization_count(), 1);

  const Eigen::VectorXd by_nested_dissection = solve();
  EXPECT_TRUE(direct.nested_dissection());
  EXPECT_EQ(direct.factorization_count(), 2);
  const double scale_n = problem.rhs.lpNorm<Eigen::Infinity>();
  EXPECT_LT(direct_residual_n(problem, by_nested_dissection), 1e-9 * scale_n);
  EXPECT_LT((by_nested_dissection - by_minimum_degree).lpNorm<Eigen::Infinity>(),
            1e-12 * by_minimum_degree.lpNorm<Eigen::Infinity>());

  std::array<Eigen::VectorXd, 2> results;
  for (int threads = 1; threads <= 2; ++threads) {
    const test::ScopedThreadCount count(threads);
    results[threads - 1] = solve();
  }
  EXPECT_EQ(direct.factorization_count(), 2);  // and it stays
  EXPECT_TRUE((results[0].array() == results[1].array()).all());
}

// the minimisers' preconditioner sweeps in float: within float round-off of the exact solve,
// under both orderings, with the same bits on one and two threads
TEST(PdDirectSolver, SolvesInSinglePrecisionWithinFloatRoundOff) {
  State state;
  const LinearProblem problem =
      make_problem(test::grid_model(30, 30, 0.02, 0.001, 3000.0, 0.0, state), state, 1.0 / 30.0, 7);
  const Eigen::VectorXd exact = direct_solution(problem);
  const double scale_m = exact.lpNorm<Eigen::Infinity>();
  PdDirectSolver single;
  single.set_precision(SolvePrecision::single);
  const auto solve = [&] {
    Eigen::VectorXd p = problem.start;
    EXPECT_TRUE(single.solve(problem.system, problem.rhs, p));
    return p;
  };
  const Eigen::VectorXd by_minimum_degree = solve();
  const double error_m = (by_minimum_degree - exact).lpNorm<Eigen::Infinity>();
  EXPECT_LT(error_m, 1e-5 * scale_m);
  EXPECT_GT(error_m, 0.0);  // it did sweep in float
  for (int k = 1; k < PdDirectSolver::solves_before_nested_dissection; ++k) solve();
  std::array<Eigen::VectorXd, 2> results;
  for (int threads = 1; threads <= 2; ++threads) {
    const test::ScopedThreadCount count(threads);
    results[threads - 1] = solve();
  }
  EXPECT_TRUE(single.nested_dissection());
  EXPECT_LT((results[0] - exact).lpNorm<Eigen::Infinity>(), 1e-5 * scale_m);
  EXPECT_TRUE((results[0].array() == results[1].array()).all());
  for (int i = 0; i < problem.model.particle_count(); ++i) {  // pinned ones untouched
    if (problem.model.pinned[i]) {
      EXPECT_EQ(results[0].segment<3>(3 * i), problem.start.segment<3>(3 * i));
    }
  }
  // a copy keeps the precision: it sweeps in float too
  PdDirectSolver copy = single;
  Eigen::VectorXd p = problem.start;
  EXPECT_TRUE(copy.solve(problem.system, problem.rhs, p));
  EXPECT_TRUE((p.array() == by_minimum_degree.array()).all());
}

TEST(PdSystem, RebuildsOnlyWhenTheModelOrTheTimeStepChanges) {
  State state;
  SpringModel model = test::grid_model(6, 5, 0.05, 0.002, 200.0, 0.0, state);
  PdSystem system;
  PdDirectSolver direct;
  EXPECT_TRUE(update_pd_system(model, 0.01, system));
  EXPECT_TRUE(direct.factorize(system));
  EXPECT_FALSE(update_pd_system(model, 0.01, system));
  EXPECT_TRUE(direct.factorize(system));
  EXPECT_EQ(direct.factorization_count(), 1);
  EXPECT_TRUE(update_pd_system(model, 0.02, system));  // new h
  EXPECT_TRUE(direct.factorize(system));
  EXPECT_EQ(direct.factorization_count(), 2);
  model.stiffness[3] *= 2.0;  // new stiffness: a changed model is finalized again
  finalize_model(model);
  EXPECT_TRUE(update_pd_system(model, 0.02, system));
  EXPECT_FALSE(update_pd_system(model, 0.02, system));
  SpringModel same = model;  // a copy is the same model
  EXPECT_FALSE(update_pd_system(same, 0.02, system));
  model.pinned[4] = 1;  // new pin
  finalize_model(model);
  EXPECT_TRUE(update_pd_system(model, 0.02, system));
  EXPECT_EQ(system.free_index[4], -1);
  EXPECT_EQ(system.free_particles.size(), static_cast<std::size_t>(model.particle_count() - 1));
  EXPECT_TRUE(is_valid_coloring(model, system.coloring));
  // a copied solver starts unfactorised
  PdDirectSolver copy = direct;
  EXPECT_EQ(copy.factorization_count(), 0);
}

// every free particle in exactly one block, and no spring between two blocks of one colour
void expect_valid_blocks(const SpringModel& model, const PdSystem& system) {
  const std::vector<int>& offsets = system.block_offsets;
  ASSERT_FALSE(offsets.empty());
  EXPECT_EQ(offsets.front(), 0);
  EXPECT_EQ(offsets.back(), static_cast<int>(system.free_particles.size()));
  EXPECT_TRUE(std::is_sorted(offsets.begin(), offsets.end()));
  const int blocks = static_cast<int>(offsets.size()) - 1;
  ASSERT_EQ(static_cast<int>(system.block_coloring.color.size()), blocks);
  std::vector<int> block_of(model.particle_count(), -1);
  for (int b = 0; b < blocks; ++b) {
    for (int f = offsets[b]; f < offsets[b + 1]; ++f) block_of[system.free_particles[f]] = b;
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const int a = block_of[model.springs(s, 0)], b = block_of[model.springs(s, 1)];
    if (a < 0 || b < 0 || a == b) continue;
    EXPECT_NE(system.block_coloring.color[a], system.block_coloring.color[b]) << "spring " << s;
  }
}

TEST(PdSystem, NoSpringJoinsTwoBlocksOfOneColour) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    State state;
    // 1999 free particles: 32 blocks of 64 (the last shorter), joined at random
    SpringModel model = test::random_model(2000, 6000, 0, seed, state);
    model.pinned[seed] = 1;
    finalize_model(model);
    PdSystem system;
    update_pd_system(model, 0.01, system);
    SCOPED_TRACE(seed);
    EXPECT_EQ(system.block_offsets.size(), 33u);
    expect_valid_blocks(model, system);
  }
  // a 100 x 100 grid numbered row by row: blocks are bands of rows, and few colours suffice
  State state;
  const SpringModel grid = test::grid_model(100, 100, 0.01, 0.002, 200.0, 0.0, state);
  PdSystem system;
  update_pd_system(grid, 0.01, system);
  expect_valid_blocks(grid, system);
  EXPECT_LE(system.block_coloring.color_count(), 3);
}

}  // namespace
}  // namespace tissu
