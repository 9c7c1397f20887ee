// The aggregation multigrid V-cycle on Newton Hessians of the stiff hanging sheet: a symmetric
// positive definite preconditioner, conjugate-gradient iterations that do not grow with the sheet's
// size, its hierarchy rebuilt for a new pattern; and Newton's step with either preconditioner.

#include "solver/multigrid/aggregation_multigrid.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <random>
#include <vector>

#include "solver/forces/spring_block_matrix.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/step.hpp"
#include "tests/solver/backward_euler_reference.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

// The Newton Hessian M/h^2 + sum of clamped spring blocks (N/m) of an n x n sheet of 1 m, 1 kg,
// 3000 N/m springs, two corners pinned (identity rows), stretched by 1 % and crumpled by up to
// 1 cm out of plane, at h = 1/30 s: the system the Newton integrator solves on docs/benchmarks.md's
// stiff sheet.
SymmetricBlockMatrix sheet_hessian(int n, unsigned seed, SpringModel& model) {
  State state;
  model = test::grid_model(n, n, 1.0 / (n - 1), 1.0 / (n * n), 3000.0, 0.0, state);
  model.pinned[n * (n - 1)] = 1;
  model.pinned[n * n - 1] = 1;
  finalize_model(model);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> crumple(-0.01, 0.01);
  for (int p = 0; p < model.particle_count(); ++p) {
    state.x.segment<3>(3 * p) *= 1.01;
    state.x[3 * p + 2] += crumple(random);
  }
  std::vector<SymmetricBlock> blocks(model.spring_count());
  for (int s = 0; s < model.spring_count(); ++s) {
    blocks[s] = upper_triangle(-spring_force_jacobian_clamped(
        state.x.segment<3>(3 * model.springs(s, 0)), state.x.segment<3>(3 * model.springs(s, 1)),
        model.stiffness[s], model.rest_length[s]));
  }
  const double h = 1.0 / 30.0;
  SpringBlockPattern pattern;
  update_spring_block_pattern(model, pattern);
  SymmetricBlockMatrix hessian;
  assemble_symmetric_spring_block_matrix(model, pattern, blocks,
                                         Eigen::VectorXd(model.mass / (h * h)), true, hessian);
  return hessian;
}

// Conjugate gradient on A x = b from 0, preconditioned by one V-cycle, to |r| <= tolerance |b|;
// returns the iterations.
int preconditioned_cg(const SymmetricBlockMatrix& a, AggregationMultigrid& multigrid,
                      const Eigen::VectorXd& b, double tolerance, Eigen::VectorXd& x) {
  x.setZero(b.size());
  Eigen::VectorXd r = b, z, p, ap;
  multigrid.apply(r, z);
  p = z;
  double rz = r.dot(z);
  int iteration = 0;
  while (r.norm() > tolerance * b.norm() && iteration < 1000) {
    symmetric_block_product(a, p, ap);
    const double alpha = rz / p.dot(ap);
    x += alpha * p;
    r -= alpha * ap;
    multigrid.apply(r, z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
    ++iteration;
  }
  return iteration;
}

TEST(AggregationMultigrid, TheVCycleIsSymmetricAndPositiveDefinite) {
  SpringModel model;
  const SymmetricBlockMatrix hessian = sheet_hessian(31, 1, model);
  AggregationMultigrid multigrid;
  multigrid.set_operator(hessian, model.identity);
  EXPECT_GE(multigrid.level_count(), 3);
  EXPECT_LE(multigrid.node_count(multigrid.level_count() - 1), 64);
  for (unsigned seed = 0; seed < 5; ++seed) {
    const Eigen::VectorXd r1 = test::random_free_vector(model, 2 * seed);
    const Eigen::VectorXd r2 = test::random_free_vector(model, 2 * seed + 1);
    Eigen::VectorXd z1, z2;
    multigrid.apply(r1, z1);
    multigrid.apply(r2, z2);
    const double scale = r1.norm() * z2.norm();
    EXPECT_NEAR(r1.dot(z2), r2.dot(z1), 1e-12 * scale) << "seed " << seed;
    EXPECT_GT(r1.dot(z1), 0.0) << "seed " << seed;
    for (int p = 0; p < model.particle_count(); ++p) {  // pinned particles do not move
      if (model.pinned[p]) {
        EXPECT_EQ(Eigen::Vector3d(z1.segment<3>(3 * p)), Eigen::Vector3d::Zero());
      }
    }
  }
}

TEST(AggregationMultigrid, ConjugateGradientIterationsDoNotGrowWithTheSheet) {
  // the PD matrix, blind to the taut sheet's softness across its springs, needs 15.7 iterations
  // per Newton iteration at only 1/4 of the residual (docs/benchmarks.md); the V-cycle on the
  // Hessian itself solves to 1e-8 in a count that stays put from 41 x 41 to 81 x 81 (57 and 55)
  std::vector<int> iterations;
  for (const int n : {41, 81}) {
    SpringModel model;
    const SymmetricBlockMatrix hessian = sheet_hessian(n, 3, model);
    AggregationMultigrid multigrid;
    multigrid.set_operator(hessian, model.identity);
    const Eigen::VectorXd b = test::random_free_vector(model, 4);
    Eigen::VectorXd x;
    iterations.push_back(preconditioned_cg(hessian, multigrid, b, 1e-8, x));
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct{to_sparse(hessian)};
    const Eigen::VectorXd exact = direct.solve(b);
    EXPECT_LT((x - exact).norm(), 1e-6 * exact.norm()) << n << " x " << n;
  }
  EXPECT_LT(iterations.back(), 120);
  EXPECT_LT(iterations.back(), 1.25 * iterations.front()) << iterations[0] << ", " << iterations[1];
}

TEST(AggregationMultigrid, ANewPatternKeyRebuildsTheHierarchy) {
  SpringModel small, large;
  const SymmetricBlockMatrix first = sheet_hessian(21, 5, small);
  const SymmetricBlockMatrix second = sheet_hessian(33, 6, large);
  AggregationMultigrid reused, fresh;
  reused.set_operator(first, small.identity);
  reused.set_operator(second, large.identity);
  fresh.set_operator(second, large.identity);
  const Eigen::VectorXd r = test::random_free_vector(large, 7);
  Eigen::VectorXd from_reused, from_fresh;
  reused.apply(r, from_reused);
  fresh.apply(r, from_fresh);
  EXPECT_EQ(reused.level_count(), fresh.level_count());
  EXPECT_TRUE((from_reused.array() == from_fresh.array()).all());
}

TEST(AggregationMultigrid, NewtonReachesTheExactBackwardEulerStepWithEitherPreconditioner) {
  for (const NewtonPreconditioner preconditioner :
       {NewtonPreconditioner::multigrid, NewtonPreconditioner::pd_matrix}) {
    State state;
    const SpringModel model = test::perturbed_sheet(state, 0.0, 7);
    SolverParams params;
    params.integrator = Integrator::newton;
    params.time_step = 1.0 / 60.0;
    params.environment.wind.air_density = 0.0;
    params.newton.tolerance = 1e-12;
    params.newton.max_iterations = 1000;
    params.newton.preconditioner = preconditioner;
    const Eigen::VectorXd reference =
        test::backward_euler_positions(model, state, params.time_step, params.environment.gravity);
    const double displacement = (reference - state.x).lpNorm<Eigen::Infinity>();
    ASSERT_EQ(step(model, params, state), StepStatus::ok) << to_string(preconditioner);
    EXPECT_LT((state.x - reference).lpNorm<Eigen::Infinity>(), 1e-9 * displacement)
        << to_string(preconditioner);
  }
}

}  // namespace
}  // namespace tissu
