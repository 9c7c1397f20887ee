#include "solver/pd/pd_system.hpp"

#include <algorithm>
#include <atomic>

namespace tissu {
namespace {

bool is_built_for(const SpringModel& model, double h, const PdSystem& system) {
  return system.generation != 0 && system.built_for_model == model.identity &&
         system.built_time_step == h;
}

std::uint64_t next_generation() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

/// Blocks of consecutive free particles for block Gauss-Seidel, sized from the model alone (so
/// the sweep is the same for any thread count): about 64 blocks, of 64 to 4096 particles (a
/// block's rows and positions, at most about 0.8 MB, are read once per sweep, in order). On a grid
/// numbered row by row a block is a band of rows, and the block graph needs 2 or 3 colours; on a
/// refined mesh, whose new particles are numbered last, blocks are less compact and need more.
void build_blocks(PdSystem& system) {
  const int free_count = static_cast<int>(system.free_particles.size());
  const int block_size = std::clamp(free_count / 64, 64, 4096);
  const int blocks = (free_count + block_size - 1) / block_size;
  system.block_offsets.resize(blocks + 1);
  for (int b = 0; b <= blocks; ++b) system.block_offsets[b] = std::min(b * block_size, free_count);
  system.block_of.assign(system.pinned.size(), -1);
  for (int f = 0; f < free_count; ++f) system.block_of[system.free_particles[f]] = f / block_size;
  // block b's neighbours: the other blocks its particles' springs reach, each listed once
  system.block_graph_offsets.assign(1, 0);
  system.block_graph_neighbours.clear();
  system.scratch.assign(blocks, -1);  // scratch[c] == b once block c is listed for block b
  for (int b = 0; b < blocks; ++b) {
    for (int f = system.block_offsets[b]; f < system.block_offsets[b + 1]; ++f) {
      const int i = system.free_particles[f];
      for (int e = system.neighbour_offsets[i]; e < system.neighbour_offsets[i + 1]; ++e) {
        const int other = system.block_of[system.neighbours[e]];
        if (other < 0 || other == b || system.scratch[other] == b) continue;
        system.scratch[other] = b;
        system.block_graph_neighbours.push_back(other);
      }
    }
    system.block_graph_offsets.push_back(static_cast<int>(system.block_graph_neighbours.size()));
  }
  color_particles(system.block_graph_offsets, system.block_graph_neighbours, system.block_coloring,
                  system.scratch);
}

}  // namespace

bool update_pd_system(const SpringModel& model, double h, PdSystem& system) {
  if (is_built_for(model, h, system)) return false;
  const int particles = model.particle_count();
  const ParticleSpringIncidence& incidence = model.incidence;
  system.built_for_model = model.identity;
  system.built_time_step = h;
  system.generation = next_generation();

  system.neighbour_offsets = incidence.offsets;
  const std::size_t entries = incidence.springs.size();
  system.neighbours.resize(entries);
  system.weights.resize(entries);
  for (std::size_t e = 0; e < entries; ++e) {
    const int s = incidence.springs[e];
    system.neighbours[e] = model.springs(s, incidence.first_end[e] ? 1 : 0);
    system.weights[e] = model.stiffness[s];
  }

  system.inertia = model.mass / (h * h);
  system.diagonal = system.inertia;
  system.pinned.resize(particles);
  system.free_index.assign(particles, -1);
  system.free_particles.clear();
  system.jacobi_radius_bound = 0.0;
  for (int p = 0; p < particles; ++p) {
    system.pinned[p] = model.inverse_mass[p] == 0.0 ? 1 : 0;
    double coupling = 0.0;
    for (int e = incidence.offsets[p]; e < incidence.offsets[p + 1]; ++e) {
      coupling += system.weights[e];
    }
    system.diagonal[p] += coupling;
    if (system.pinned[p]) continue;
    system.free_index[p] = static_cast<int>(system.free_particles.size());
    system.free_particles.push_back(p);
    system.jacobi_radius_bound =
        std::max(system.jacobi_radius_bound, coupling / system.diagonal[p]);
  }

  color_particles(system.neighbour_offsets, system.neighbours, system.coloring, system.scratch);
  const ParticleColoring& coloring = system.coloring;
  system.free_color_offsets.assign(1, 0);
  system.free_color_order.clear();
  for (int c = 0; c < coloring.color_count(); ++c) {
    for (int k = coloring.color_offsets[c]; k < coloring.color_offsets[c + 1]; ++k) {
      if (!system.pinned[coloring.order[k]]) system.free_color_order.push_back(coloring.order[k]);
    }
    system.free_color_offsets.push_back(static_cast<int>(system.free_color_order.size()));
  }
  build_blocks(system);
  return true;
}

}  // namespace tissu
