// Self-collision on a folded sheet: the broad phase over the whole cloth, the search again of the
// pairs of a few particles that moved, and whole steps of self-collision handling, with every
// particle moving or only a few. Results and the machine: docs/benchmarks.md.
//
//   OMP_NUM_THREADS=1 ./build/release/bench/self_collision_bench --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true   (one command line)

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "solver/collision/collision_pairs.hpp"
#include "solver/collision/self_collision.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/compile.hpp"
#include "topology/grid_mesh.hpp"

namespace tissu {
namespace {

constexpr double thickness_m = 0.004;
constexpr double step_s = 1.0 / 60.0;

/// A 1 m square of n x n particles folded in half: the far half lies 1 cm over the near half, both
/// rippled by 1 cm waves, so that the layers are within reach of each other and neighbours are
/// not coplanar.
CompiledCloth folded_sheet(int particles_per_side) {
  GridOptions grid;
  grid.v_axis = Eigen::Vector3d::UnitY();
  grid.cells_u = grid.cells_v = particles_per_side - 1;
  SpringSettings springs;
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(grid), 0.2, springs, lcc);
  CompiledCloth cloth = compile(lcc);
  for (int p = 0; p < cloth.model.particle_count(); ++p) {
    Eigen::Ref<Eigen::Vector3d> x = cloth.state.x.segment<3>(3 * p);
    const bool far_half = x.x() > 0.5;
    const double ripple_m = 0.01 * std::sin(2.0 * std::numbers::pi * 4.0 * x.y());
    x = Eigen::Vector3d(far_half ? 1.0 - x.x() : x.x(), x.y(), ripple_m + (far_half ? 0.01 : 0.0));
  }
  return cloth;
}

/// Where the sheet's particles are after a step in which all of them fall by `fall_m` and tremble
/// by up to 0.3 mm, and those of its hem (y below `hem_m`) slide together by 8 mm in a direction
/// drawn from `random`, as the hem of a settled drape slides on the floor.
Eigen::VectorXd stepped(const Eigen::VectorXd& x, double hem_m, double fall_m,
                        std::mt19937& random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double angle = std::numbers::pi * unit(random);
  const Eigen::Vector3d slide(0.008 * std::cos(angle), 0.008 * std::sin(angle), 0.0);
  Eigen::VectorXd end_x = x;
  for (Eigen::Index i = 0; i < x.size() / 3; ++i) {
    Eigen::Ref<Eigen::Vector3d> end = end_x.segment<3>(3 * i);
    if (end.y() < hem_m) end += slide;
    end += Eigen::Vector3d(0.0, 0.0, -fall_m) +
           0.0003 * Eigen::Vector3d(unit(random), unit(random), unit(random));
  }
  return end_x;
}

/// The pairs within the thickness over a step in which the sheet falls by 2 cm: the whole cloth's
/// broad phase.
void BM_WholeSearch(benchmark::State& state) {
  const CompiledCloth cloth = folded_sheet(static_cast<int>(state.range(0)));
  std::mt19937 random(1);
  const Eigen::VectorXd end_x = stepped(cloth.state.x, 0.0, 0.02, random);
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs =
        collision_candidates(cloth.model, cloth.state.x, end_x, thickness_m, thickness_m).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["particles"] = cloth.model.particle_count();
  state.counters["pairs"] = static_cast<double>(pairs);
}
BENCHMARK(BM_WholeSearch)->Arg(49)->Arg(97)->Unit(benchmark::kMillisecond);

/// The pairs of 1 % of the particles searched again against the whole cloth, as the kept pairs
/// are updated when a few particles leave their boxes.
void BM_SearchOfMovedParticles(benchmark::State& state) {
  const CompiledCloth cloth = folded_sheet(static_cast<int>(state.range(0)));
  const int particles = cloth.model.particle_count();
  std::vector<char> moved(particles, 0);
  for (int p = 0; p < particles; p += 100) moved[p] = 1;
  const ParticleBoxes boxes = ParticleBoxes::swept(cloth.state.x, cloth.state.x);
  // the thickness and the skin, as the kept pairs are searched
  const double margin_m =
      thickness_m + std::min(0.01, 0.5 * mean_edge_length_m(cloth.model, boxes));
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = collision_candidates_touching(cloth.model, boxes, margin_m, thickness_m, moved).size();
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["particles"] = particles;
  state.counters["pairs"] = static_cast<double>(pairs);
}
BENCHMARK(BM_SearchOfMovedParticles)->Arg(49)->Arg(97)->Unit(benchmark::kMillisecond);

/// One step of self-collision handling (broad phase with the kept pairs, proximities, impulses)
/// per iteration: with the second argument 0, from the folded sheet to a fresh end, a settled
/// sheet whose particles tremble while its hem (its first 2 cm, 2 to 3 % of the particles)
/// slides; with 1, the trembling sheet falling by 2 cm per step, each step from the last one's
/// end (1.2 m/s, as a dropped cloth after 12 cm).
void BM_SelfCollisionStep(benchmark::State& state) {
  const CompiledCloth cloth = folded_sheet(static_cast<int>(state.range(0)));
  const bool falling = state.range(1) == 1;
  SelfCollisionOptions options;
  options.enabled = true;
  options.thickness_m = thickness_m;
  SelfCollisionCache cache;
  std::mt19937 random(2);
  std::vector<Eigen::VectorXd> ends;  // settled: the ends; falling: the trembles
  for (int k = 0; k < 16; ++k) {
    ends.push_back(falling
                       ? Eigen::VectorXd(stepped(cloth.state.x, 0.0, 0.0, random) - cloth.state.x)
                       : stepped(cloth.state.x, 0.02, 0.0, random));
  }
  const Eigen::Vector3d fall_m(0.0, 0.0, -0.02);  // per step
  const auto falling_x = [&](int step) {
    return relative_to(cloth.state.x + ends[step % ends.size()], -step * fall_m);
  };
  State moved = cloth.state;
  int steps = 0;
  const auto one_step = [&] {
    const Eigen::VectorXd start_x = falling ? falling_x(steps) : cloth.state.x;
    moved.x = falling ? falling_x(steps + 1) : ends[steps % ends.size()];
    ++steps;
    moved.v.setZero();
    return resolve_self_collisions(cloth.model, options, step_s, start_x, Eigen::Matrix3Xd(), cache,
                                   moved);
  };
  one_step();  // the first search of the whole cloth, untimed
  double candidates = 0.0, proximities = 0.0;
  for (auto _ : state) {
    const SelfCollisionReport report = one_step();
    candidates += report.candidates;
    proximities += report.proximities;
  }
  steps -= 1;
  state.counters["particles"] = cloth.model.particle_count();
  state.counters["candidates"] = candidates / steps;
  state.counters["proximities"] = proximities / steps;
  state.counters["kept_pairs"] = static_cast<double>(cache.pairs.size());
}
BENCHMARK(BM_SelfCollisionStep)
    ->Args({49, 0})
    ->Args({49, 1})
    ->Args({97, 0})
    ->Args({97, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tissu

BENCHMARK_MAIN();
