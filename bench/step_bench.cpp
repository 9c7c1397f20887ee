// Wall time of one solver step on a hanging square cloth, per integrator, grid size and thread
// count. Results and the machine: docs/benchmarks.md.

#include <benchmark/benchmark.h>
#include <omp.h>

#include "solver/step.hpp"
#include "topology/apply_pins.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/compile.hpp"
#include "topology/grid_mesh.hpp"

namespace tissu {
namespace {

/// A 1 m square of n x n particles, 0.2 kg/m^2, structural and bending springs, top edge pinned.
CompiledCloth square_cloth(int particles_per_side) {
  GridOptions grid;
  grid.cells_u = grid.cells_v = particles_per_side - 1;
  SpringSettings springs;
  springs.structural = {true, 1000.0, 0.01};  // light damping keeps explicit steps stable
  springs.bending = {true, 4.0, 0.001};
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(grid), 0.2, springs, lcc);
  PinSelector top;
  top.side = Side::top;
  apply_pins(lcc, {top}, ClothFrame{});
  return compile(lcc);
}

/// Stable time steps: implicit at the curtain demo's; explicit below 2 / omega_max, where the
/// highest lattice mode omega_max ~ sqrt(12 k / m) is 15,000 rad/s on the 64 x 64 grid and
/// 31,000 rad/s on the 128 x 128 one (m = 0.2 kg / n^2).
double time_step_s(Integrator integrator) {
  return integrator == Integrator::implicit_euler ? 1.0 / 300.0 : 2e-5;
}

/// Times one step per iteration, after 20 untimed ones (the cloth starts falling and the
/// workspace is sized).
void time_steps(benchmark::State& bench, const SolverParams& params, CompiledCloth& cloth,
                StepWorkspace& workspace) {
  for (int n = 0; n < 20; ++n) step(cloth.model, params, cloth.state, workspace);
  for (auto _ : bench) {
    const StepStatus status = step(cloth.model, params, cloth.state, workspace);
    if (status == StepStatus::non_finite) bench.SkipWithError("non-finite state");
  }
}

void BM_Step(benchmark::State& bench) {
  const auto integrator = static_cast<Integrator>(bench.range(0));
  const int side = static_cast<int>(bench.range(1));
  omp_set_num_threads(static_cast<int>(bench.range(2)));
  CompiledCloth cloth = square_cloth(side);
  SolverParams params;
  params.integrator = integrator;
  params.time_step = time_step_s(integrator);
  params.environment.wind.velocity = Eigen::Vector3d(0.0, 1.0, 0.0);
  StepWorkspace workspace;
  time_steps(bench, params, cloth, workspace);
  bench.counters["particles"] = cloth.model.particle_count();
  bench.counters["springs"] = cloth.model.spring_count();
  bench.counters["threads"] = static_cast<double>(bench.range(2));
}

/// The same square from a material: E h = 1000 N/m (the raw springs' k), nu = 1/3, 0.2 kg/m^2,
/// by van Gelder's springs alone or by Delingette's springs and couplings.
CompiledCloth material_cloth(int particles_per_side, StiffnessFormulation formulation) {
  GridOptions grid;
  grid.cells_u = grid.cells_v = particles_per_side - 1;
  SpringSettings springs;
  springs.structural = {true, 0.0, 0.01};
  springs.bending = {true, 0.0, 0.001};
  springs.material = Material{2e6, 1.0 / 3.0, 5e-4, 400.0, formulation};
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(grid), springs.material->areal_density_kg_per_m2(), springs,
                      lcc);
  PinSelector top;
  top.side = Side::top;
  apply_pins(lcc, {top}, ClothFrame{});
  return compile(lcc);
}

/// What Delingette's couplings cost an implicit Euler step, against springs alone.
void BM_ImplicitStepMaterial(benchmark::State& bench) {
  const auto formulation = static_cast<StiffnessFormulation>(bench.range(0));
  omp_set_num_threads(static_cast<int>(bench.range(2)));
  CompiledCloth cloth = material_cloth(static_cast<int>(bench.range(1)), formulation);
  SolverParams params;
  params.integrator = Integrator::implicit_euler;
  params.time_step = time_step_s(Integrator::implicit_euler);
  StepWorkspace workspace;
  time_steps(bench, params, cloth, workspace);
  bench.counters["springs"] = cloth.model.spring_count();
  bench.counters["couplings"] = static_cast<double>(cloth.model.couplings.rows());
  bench.counters["cg_iterations"] = workspace.implicit.cg_iterations;
}

void material_arguments(benchmark::internal::Benchmark* b) {
  b->ArgNames({"formulation", "side", "threads"});
  for (const StiffnessFormulation formulation :
       {StiffnessFormulation::van_gelder1998, StiffnessFormulation::delingette2008}) {
    for (int side : {64, 128}) {
      for (int threads : {1, 2}) b->Args({static_cast<int>(formulation), side, threads});
    }
  }
}

void step_arguments(benchmark::internal::Benchmark* b) {
  b->ArgNames({"integrator", "side", "threads"});
  for (int integrator : {0, 1, 2}) {
    for (int side : {64, 128}) {
      for (int threads : {1, 2}) b->Args({integrator, side, threads});
    }
  }
}

BENCHMARK(BM_Step)->Apply(step_arguments)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ImplicitStepMaterial)
    ->Apply(material_arguments)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace tissu

BENCHMARK_MAIN();
