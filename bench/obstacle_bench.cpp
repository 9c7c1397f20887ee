// Mesh obstacle queries: signed distance of points near a closed triangle mesh (the hierarchy's
// nearest point, the sign by a ray's crossings), the hierarchical winding number that the sign
// falls back to; and the cost of an animated mesh's surface at a new instant (what each step of
// a moving body pays).
//
//   ./build/release/bench/obstacle_bench --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true   (one command line)

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "topology/mesh_obstacle.hpp"
#include "topology/winding_number.hpp"

namespace tissu {
namespace {

/// A closed UV sphere of radius 0.25 m, n meridians and n / 2 bands: n^2 - 2n triangles.
IndexedMesh sphere(int n) {
  IndexedMesh m;
  const int bands = n / 2;
  m.vertices.emplace_back(0.0, 0.0, 0.25);
  for (int b = 1; b < bands; ++b) {
    const double phi = std::numbers::pi * b / bands;
    for (int k = 0; k < n; ++k) {
      const double theta = 2.0 * std::numbers::pi * k / n;
      m.vertices.emplace_back(0.25 * std::sin(phi) * std::cos(theta),
                              0.25 * std::sin(phi) * std::sin(theta), 0.25 * std::cos(phi));
    }
  }
  m.vertices.emplace_back(0.0, 0.0, -0.25);
  const auto ring = [n](int b, int k) { return 1 + (b - 1) * n + (k % n); };
  const int south = static_cast<int>(m.vertices.size()) - 1;
  for (int k = 0; k < n; ++k) {
    m.faces.push_back({0, ring(1, k), ring(1, k + 1)});
    for (int b = 1; b + 1 < bands; ++b) {
      m.faces.push_back({ring(b, k), ring(b + 1, k), ring(b + 1, k + 1)});
      m.faces.push_back({ring(b, k), ring(b + 1, k + 1), ring(b, k + 1)});
    }
    m.faces.push_back({ring(bands - 1, k), south, ring(bands - 1, k + 1)});
  }
  return m;
}

/// Points within 2 cm of the sphere's surface, where draped cloth is.
std::vector<Eigen::Vector3d> near_surface_points(int count) {
  std::mt19937 random(3);
  std::normal_distribution<double> direction(0.0, 1.0);
  std::uniform_real_distribution<double> radius(0.23, 0.27);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d d(direction(random), direction(random), direction(random));
    points.push_back(radius(random) * d.normalized());
  }
  return points;
}

/// Signed distance through make_mesh_surface (the hierarchy's nearest point, sign by crossings).
void SignedDistance(benchmark::State& state) {
  const IndexedMesh mesh = sphere(static_cast<int>(state.range(0)));
  const auto surface = make_mesh_surface(mesh);
  const std::vector<Eigen::Vector3d> points = near_surface_points(4096);
  for (auto _ : state) {
    double sum = 0.0;
    for (const Eigen::Vector3d& x : points) sum += surface->distance(x).distance_m;
    benchmark::DoNotOptimize(sum);
  }
  state.counters["triangles"] = static_cast<double>(mesh.faces.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}
BENCHMARK(SignedDistance)->Arg(32)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond);

/// The winding number alone, hierarchically (the sign's fallback; the sign itself until
/// 2026-12-06).
void WindingNumber(benchmark::State& state) {
  const IndexedMesh mesh = sphere(static_cast<int>(state.range(0)));
  std::vector<Eigen::Vector3d> corners;
  for (const std::vector<int>& f : mesh.faces) {
    for (int v : f) corners.push_back(mesh.vertices[v]);
  }
  const WindingNumberTree tree(corners);
  const std::vector<Eigen::Vector3d> points = near_surface_points(4096);
  for (auto _ : state) {
    double sum = 0.0;
    for (const Eigen::Vector3d& x : points) sum += tree.winding_number(x);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["triangles"] = static_cast<double>(mesh.faces.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}
BENCHMARK(WindingNumber)->Arg(32)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond);

/// An animated sphere's surface at a new instant each iteration, and its first query: its vertices
/// interpolated, its hierarchy's boxes refitted to them (an AABB tree built afresh, with CGAL's
/// kd-tree of hints, until 2026-12-06).
void AnimatedSurfaceAtANewInstant(benchmark::State& state) {
  const IndexedMesh mesh = sphere(static_cast<int>(state.range(0)));
  std::vector<Eigen::Vector3d> moved = mesh.vertices;
  for (Eigen::Vector3d& x : moved) x *= 1.5;
  const auto animation = make_mesh_animation(mesh, {{0.0, 1.0}, {mesh.vertices, moved}});
  double time_s = 0.0;
  for (auto _ : state) {
    time_s = std::fmod(time_s + 0.001, 1.0);  // never the instant of a kept surface
    benchmark::DoNotOptimize(animation->at(time_s)->distance({0.3, 0.2, 0.1}));
  }
  state.counters["triangles"] = static_cast<double>(mesh.faces.size());
}
BENCHMARK(AnimatedSurfaceAtANewInstant)
    ->Arg(32)
    ->Arg(64)
    ->Arg(128)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tissu

BENCHMARK_MAIN();
