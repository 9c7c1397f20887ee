// What one OpenMP parallel loop costs on this machine by waiting policy: a loop of `items` light
// updates (about 11 µs of work for 6,561 items on one thread), then `gap_us` of serial work before
// the next, as in a solver step's back-to-back loops. libgomp reads its policy once, before main,
// so the policy is the environment's; run it once per policy and thread count:
//
//   OMP_NUM_THREADS=1 build/release/bench/fork_join_bench
//   OMP_NUM_THREADS=2 OMP_WAIT_POLICY=passive build/release/bench/fork_join_bench
//   OMP_NUM_THREADS=2 GOMP_SPINCOUNT=10000 build/release/bench/fork_join_bench
//
// Results (and why the tissu programs set GOMP_SPINCOUNT): docs/benchmarks.md, "2026-12-07".

#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <vector>

namespace {

void serial_work_us(double microseconds) {
  const auto start = std::chrono::steady_clock::now();
  while (
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() <
      microseconds) {
  }
}

void BM_ParallelLoop(benchmark::State& bench) {
  const int items = static_cast<int>(bench.range(0));
  const double gap_us = static_cast<double>(bench.range(1));
  std::vector<double> a(items, 1.0), b(items, 2.0);
  for (auto _ : bench) {
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (int i = 0; i < items; ++i) a[i] = 0.999 * a[i] + b[i];
    bench.SetIterationTime(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    benchmark::DoNotOptimize(a.data());
    serial_work_us(gap_us);  // not timed: the serial work between two loops
  }
  bench.counters["threads"] = omp_get_max_threads();
}

BENCHMARK(BM_ParallelLoop)
    ->ArgNames({"items", "gap_us"})
    ->Args({6561, 0})
    ->Args({6561, 20})
    ->Args({6561, 200})
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
