// A peer, not part of tissu: Bullet's classic soft body (btSoftBody in a btSoftRigidDynamicsWorld,
// position-based link constraints) on the hanging sheet of integrator_bench's HangingSheet, so
// that tissu's solvers can be compared with Bullet in the same run (issue 16).
//
// BulletSheet/<N>: Liu et al. 2013's sheet, 1 m x 1 m in the z = 0 plane, N x N particles of
// 1/N^2 kg each, the two corners of one edge pinned (mass 0), gravity -9.81 m/s^2 along z, no
// drag, released from rest; h = 1/30 s, one internal step per frame, 90 frames. The springs are
// btSoftBodyHelpers::CreatePatch's links (the grid edges and one diagonal per quad) and the
// links of generateBendingConstraints(2) (every pair two links apart: the other diagonal, the
// skip-one grid pairs and the knight's moves across the diagonals; appended here in its order,
// since Bullet's own crashes at 256 x 256), all of one material with linear stiffness
// m_kLST = 1 (fully stiff), solved by 10 position iterations (m_cfg.piterations).
// Counters as HangingSheet's: ms_per_frame (the 90 steps, not building the world), lowest point
// after the last frame (m, the pins at 0) and the stretch of the structural links (between grid
// neighbours along u or v, %): median, 90th percentile, largest, and the fraction stretched more
// than 10 % (frac_over_10pct).
//
// Built only when CMake finds Bullet (Debian's libbullet-dev). Results: docs/benchmarks.md.

#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <benchmark/benchmark.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace {

constexpr int sheet_frames = 90;
constexpr double time_step_s = 1.0 / 30.0;
constexpr double sheet_mass_kg = 1.0;

/// The links generateBendingConstraints(2, material) appends (every node pair two links apart,
/// in its order), without its #nodes^2 distance matrix: its int size overflows from 256 x 256
/// nodes on, and Bullet 3.24 then writes out of bounds.
void append_bending_links(btSoftBody& body, btSoftBody::Material* material) {
  const int n = body.m_nodes.size();
  std::vector<std::vector<int>> neighbours(n);
  for (int l = 0; l < body.m_links.size(); ++l) {
    const int a = static_cast<int>(body.m_links[l].m_n[0] - &body.m_nodes[0]);
    const int b = static_cast<int>(body.m_links[l].m_n[1] - &body.m_nodes[0]);
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  for (std::vector<int>& list : neighbours) std::sort(list.begin(), list.end());
  for (int j = 0; j < n; ++j) {
    std::vector<int> two_apart;  // i > j, a neighbour's neighbour but not a neighbour
    for (int k : neighbours[j]) {
      for (int i : neighbours[k]) {
        if (i > j && !std::binary_search(neighbours[j].begin(), neighbours[j].end(), i)) {
          two_apart.push_back(i);
        }
      }
    }
    std::sort(two_apart.begin(), two_apart.end());
    two_apart.erase(std::unique(two_apart.begin(), two_apart.end()), two_apart.end());
    for (int i : two_apart) {
      body.appendLink(i, j, material);
      body.m_links[body.m_links.size() - 1].m_bbending = 1;
    }
  }
}

/// Stretch (length / rest length - 1) of every structural link of the N x N patch, whose node
/// (ix, iy) is CreatePatch's node iy * N + ix.
std::vector<double> structural_stretches(const btSoftBody& sheet, int n) {
  const double rest_m = 1.0 / (n - 1);
  const auto position = [&](int ix, int iy) { return sheet.m_nodes[iy * n + ix].m_x; };
  std::vector<double> stretches;
  stretches.reserve(2 * n * (n - 1));
  for (int iy = 0; iy < n; ++iy) {
    for (int ix = 0; ix < n; ++ix) {
      if (ix + 1 < n)
        stretches.push_back((position(ix + 1, iy) - position(ix, iy)).length() / rest_m - 1.0);
      if (iy + 1 < n)
        stretches.push_back((position(ix, iy + 1) - position(ix, iy)).length() / rest_m - 1.0);
    }
  }
  std::sort(stretches.begin(), stretches.end());
  return stretches;
}

void BM_BulletSheet(benchmark::State& bench) {
  const int n = static_cast<int>(bench.range(0));
  double wall_s = 0.0;
  for (auto _ : bench) {
    btSoftBodyRigidBodyCollisionConfiguration collision_config;
    btCollisionDispatcher dispatcher(&collision_config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &solver, &collision_config);
    const btVector3 gravity(0, 0, -9.81);
    world.setGravity(gravity);
    btSoftBodyWorldInfo& info = world.getWorldInfo();
    info.m_gravity = gravity;
    info.m_dispatcher = &dispatcher;
    info.m_broadphase = &broadphase;
    info.m_sparsesdf.Initialize();

    // fixeds 1 + 2: nodes (0, 0) and (N - 1, 0), the two corners of the edge y = 0
    btSoftBody* sheet =
        btSoftBodyHelpers::CreatePatch(info, btVector3(0, 0, 0), btVector3(1, 0, 0),
                                       btVector3(0, 1, 0), btVector3(1, 1, 0), n, n, 1 + 2, true);
    btSoftBody::Material* material = sheet->m_materials[0];
    material->m_kLST = 1;
    append_bending_links(*sheet, material);
    sheet->m_cfg.piterations = 10;
    sheet->m_cfg.kDG = 0;  // no drag, no lift, no damping
    sheet->m_cfg.kLF = 0;
    sheet->m_cfg.kDP = 0;
    for (int i = 0; i < n * n; ++i) {
      if (sheet->m_nodes[i].m_im != 0) sheet->setMass(i, sheet_mass_kg / (n * n));
    }
    world.addSoftBody(sheet);

    int internal_steps = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < sheet_frames; ++frame) {
      internal_steps += world.stepSimulation(time_step_s, 1, time_step_s);
    }
    wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bench.SetIterationTime(wall_s);

    double lowest_m = 0.0;
    for (int i = 0; i < sheet->m_nodes.size(); ++i) {
      lowest_m = std::min(lowest_m, static_cast<double>(sheet->m_nodes[i].m_x.z()));
    }
    const std::vector<double> stretches = structural_stretches(*sheet, n);
    const auto over_10_pct =
        stretches.end() - std::upper_bound(stretches.begin(), stretches.end(), 0.1);
    bench.counters["lowest_m"] = lowest_m;
    bench.counters["median_stretch_pct"] = 100.0 * stretches[stretches.size() / 2];
    bench.counters["p90_stretch_pct"] = 100.0 * stretches[stretches.size() * 9 / 10];
    bench.counters["max_stretch_pct"] = 100.0 * stretches.back();
    bench.counters["frac_over_10pct"] = static_cast<double>(over_10_pct) / stretches.size();

    world.removeSoftBody(sheet);
    delete sheet;
    if (internal_steps != sheet_frames) {
      bench.SkipWithError("not exactly one internal step per frame");
      return;
    }
  }
  bench.counters["ms_per_frame"] = 1e3 * wall_s / sheet_frames;
  bench.counters["particles"] = n * n;
}

BENCHMARK(BM_BulletSheet)
    ->Name("BulletSheet")
    ->Arg(81)
    ->Arg(128)
    ->Arg(256)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
