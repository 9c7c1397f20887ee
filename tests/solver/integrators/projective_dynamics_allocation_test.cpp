// Projective Dynamics allocates nothing on the heap once its workspace is sized. This executable
// interposes glibc's malloc, calloc and realloc (which operator new and Eigen's aligned_malloc
// both call) and counts the calls made while `counting` is set. Left out of sanitizer builds,
// whose runtime owns malloc.

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TISSU_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define TISSU_SANITIZED_BUILD 1
#endif
#endif

#ifndef TISSU_SANITIZED_BUILD

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>

#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
}

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
void count() {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
}
}  // namespace

extern "C" {
void* malloc(std::size_t size) {
  count();
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* pointer, std::size_t size) {
  count();
  return __libc_realloc(pointer, size);
}
}

namespace tissu {
namespace {

TEST(ProjectiveDynamicsAllocation, NoHeapAllocationAfterTheFirstStep) {
  for (const PdGlobalSolver solver :
       {PdGlobalSolver::direct, PdGlobalSolver::jacobi, PdGlobalSolver::chebyshev,
        PdGlobalSolver::gauss_seidel, PdGlobalSolver::colored_gauss_seidel,
        PdGlobalSolver::block_gauss_seidel}) {
    State state;
    SpringModel model = test::grid_model(20, 20, 0.025, 0.001, 300.0, 0.0, state);
    model.pinned[0] = 1;
    model.pinned[19] = 1;
    finalize_model(model);
    SolverParams params;
    params.integrator = Integrator::projective_dynamics;
    params.time_step = 1.0 / 120.0;
    params.pd.global_solver = solver;
    params.pd.tolerance = 1e-6;  // exercises the convergence check too
    params.environment.wind.velocity = Eigen::Vector3d(0.0, 0.0, 3.0);
    StepWorkspace workspace;
    step(model, params, state, workspace);
    // the counter works: an Eigen vector allocates
    counting = true;
    const Eigen::VectorXd probe = Eigen::VectorXd::Ones(100);
    counting = false;
    EXPECT_GT(allocations.load(), 0);
    allocations = 0;
    counting = true;
    for (int n = 0; n < 5; ++n) step(model, params, state, workspace);
    counting = false;
    EXPECT_EQ(allocations.load(), 0) << "solver " << static_cast<int>(solver);
  }
}

}  // namespace
}  // namespace tissu

#endif  // TISSU_SANITIZED_BUILD
