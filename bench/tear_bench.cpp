// What tearing costs a run: the per-step check on the flat model (max_spring_strain), and, when
// the cloth does tear, a tearing pass over the complex (tear) and the recompile (compile). Square
// sheets of N x N triangle cells, stretched by 30 % so that a pass finds edges to tear. Results and
// the machine: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include "solver/spring_strain.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/compile.hpp"
#include "topology/grid_mesh.hpp"
#include "topology/tear.hpp"

namespace tissu {
namespace {

SpringSettings cloth_springs() {
  SpringSettings s;
  s.structural = {true, 1000.0, 0.5};
  s.bending = {true, 1.0, 0.01};
  return s;
}

/// A 1 m sheet of `cells` x `cells` triangle cells in the x-z plane, stretched 30 % along z.
void build_stretched_sheet(int cells, ClothComplex& lcc) {
  GridOptions grid;
  grid.cells_u = grid.cells_v = cells;
  build_cloth_complex(make_grid_mesh(grid), 0.2, cloth_springs(), lcc);
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& p = v->point();
    v->point() = Point3(p.x(), p.y(), 1.3 * p.z());
  }
}

void BM_StrainCheckPerStep(benchmark::State& state) {
  ClothComplex lcc;
  build_stretched_sheet(static_cast<int>(state.range(0)), lcc);
  const CompiledCloth cloth = compile(lcc);
  for (auto _ : state) {
    benchmark::DoNotOptimize(max_spring_strain(cloth.model, cloth.state.x, SpringKind::structural));
  }
  state.counters["particles"] = cloth.model.particle_count();
}

void BM_TearingPass(benchmark::State& state) {
  TearingOptions options;
  options.strain_threshold = 0.2;
  options.max_tears_per_step = 1;
  for (auto _ : state) {
    state.PauseTiming();
    ClothComplex lcc;
    build_stretched_sheet(static_cast<int>(state.range(0)), lcc);
    state.ResumeTiming();
    benchmark::DoNotOptimize(tear(lcc, options, 1'000'000, cloth_springs()).tears);
  }
}

void BM_Recompile(benchmark::State& state) {
  ClothComplex lcc;
  build_stretched_sheet(static_cast<int>(state.range(0)), lcc);
  for (auto _ : state) benchmark::DoNotOptimize(compile(lcc).model.spring_count());
}

BENCHMARK(BM_StrainCheckPerStep)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TearingPass)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Recompile)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tissu

BENCHMARK_MAIN();
