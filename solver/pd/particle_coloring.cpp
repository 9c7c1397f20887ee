#include "solver/pd/particle_coloring.hpp"

#include <algorithm>

#include "solver/group_by_label.hpp"

namespace tissu {

void color_particles(const std::vector<int>& offsets, const std::vector<int>& neighbours,
                     ParticleColoring& coloring, std::vector<int>& marks) {
  const int particles = static_cast<int>(offsets.size()) - 1;
  coloring.color.assign(particles, -1);
  // marks[c] == p + 1 when colour c is taken by a neighbour of p
  marks.assign(1, 0);
  int colors = 0;
  for (int p = 0; p < particles; ++p) {
    for (int e = offsets[p]; e < offsets[p + 1]; ++e) {
      const int c = coloring.color[neighbours[e]];
      if (c >= 0) marks[c] = p + 1;
    }
    int c = 0;
    while (c < colors && marks[c] == p + 1) ++c;
    if (c == colors) {
      ++colors;
      marks.push_back(0);
    }
    coloring.color[p] = c;
  }
  group_by_label(coloring.color, colors, coloring.color_offsets, coloring.order);
}

ParticleColoring color_particles(const SpringModel& model) {
  const ParticleSpringIncidence& incidence = model.incidence;
  std::vector<int> neighbours(incidence.springs.size());
  for (std::size_t e = 0; e < neighbours.size(); ++e) {
    neighbours[e] = model.springs(incidence.springs[e], incidence.first_end[e] ? 1 : 0);
  }
  ParticleColoring coloring;
  std::vector<int> marks;
  color_particles(incidence.offsets, neighbours, coloring, marks);
  return coloring;
}

bool is_valid_coloring(const SpringModel& model, const ParticleColoring& coloring) {
  const int particles = model.particle_count();
  if (static_cast<int>(coloring.color.size()) != particles ||
      static_cast<int>(coloring.order.size()) != particles || coloring.color_offsets.empty()) {
    return false;
  }
  for (int p = 0; p < particles; ++p) {
    if (coloring.color[p] < 0 || coloring.color[p] >= coloring.color_count()) return false;
  }
  for (int c = 0; c < coloring.color_count(); ++c) {
    for (int k = coloring.color_offsets[c]; k < coloring.color_offsets[c + 1]; ++k) {
      if (coloring.color[coloring.order[k]] != c) return false;
    }
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    if (coloring.color[model.springs(s, 0)] == coloring.color[model.springs(s, 1)]) return false;
  }
  return std::is_sorted(coloring.color_offsets.begin(), coloring.color_offsets.end()) &&
         coloring.color_offsets.back() == particles;
}

}  // namespace tissu
