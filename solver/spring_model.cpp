#include "solver/spring_model.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tissu {
namespace {

std::uint64_t next_model_identity() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("finalize_model: " + what);
}

void check_sizes(const SpringModel& model) {
  const auto particles = static_cast<std::size_t>(model.particle_count());
  const Eigen::Index springs = model.spring_count();
  if (model.pinned.size() != particles) {
    fail("pinned has " + std::to_string(model.pinned.size()) +
         " entries, expected #P = " + std::to_string(particles));
  }
  if (model.rest_length.size() != springs || model.stiffness.size() != springs ||
      model.damping.size() != springs || model.kind.size() != static_cast<std::size_t>(springs)) {
    fail("rest_length, stiffness, damping and kind must have #S = " + std::to_string(springs) +
         " entries");
  }
}

void check_values(const SpringModel& model) {
  const int particles = model.particle_count();
  for (int p = 0; p < particles; ++p) {
    if (!std::isfinite(model.mass[p]) || (model.mass[p] <= 0.0 && !model.pinned[p])) {
      fail("particle " + std::to_string(p) + " has mass " + std::to_string(model.mass[p]) +
           " kg, expected a finite positive mass (or a pinned particle)");
    }
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const int i = model.springs(s, 0);
    const int j = model.springs(s, 1);
    if (i < 0 || j < 0 || i >= particles || j >= particles || i == j) {
      fail("spring " + std::to_string(s) + " joins particles " + std::to_string(i) + " and " +
           std::to_string(j) + ", expected two distinct ids in [0, " + std::to_string(particles) +
           ")");
    }
    if (!(model.rest_length[s] >= 0.0) || !(model.stiffness[s] >= 0.0) ||
        !(model.damping[s] >= 0.0) || !std::isfinite(model.rest_length[s]) ||
        !std::isfinite(model.stiffness[s]) || !std::isfinite(model.damping[s])) {
      fail("spring " + std::to_string(s) + " has a negative or non-finite rest length, " +
           "stiffness or damping");
    }
  }
  if (model.coupling_stiffness.size() != model.couplings.rows()) {
    fail("coupling_stiffness must have #C = " + std::to_string(model.couplings.rows()) +
         " entries");
  }
  for (Eigen::Index c = 0; c < model.couplings.rows(); ++c) {
    const int a = model.couplings(c, 0), b = model.couplings(c, 1);
    if (a < 0 || b < 0 || a >= model.spring_count() || b >= model.spring_count() || a == b ||
        !std::isfinite(model.coupling_stiffness[c])) {
      fail("coupling " + std::to_string(c) + " joins springs " + std::to_string(a) + " and " +
           std::to_string(b) + " with stiffness " + std::to_string(model.coupling_stiffness[c]) +
           ", expected two distinct spring ids and a finite stiffness");
    }
  }
  for (Eigen::Index t = 0; t < model.triangles.rows(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int p = model.triangles(t, c);
      if (p < 0 || p >= particles) {
        fail("triangle " + std::to_string(t) + " refers to particle " + std::to_string(p) +
             ", expected an id in [0, " + std::to_string(particles) + ")");
      }
    }
  }
}

/// Counting sort of (row, id) pairs into compressed rows, ids ascending within a row when the
/// pairs come by ascending id.
void compress_rows(int rows, const std::vector<std::pair<int, int>>& entries,
                   std::vector<int>& offsets, std::vector<int>& ids) {
  offsets.assign(rows + 1, 0);
  for (const auto& [row, id] : entries) ++offsets[row + 1];
  for (int r = 0; r < rows; ++r) offsets[r + 1] += offsets[r];
  ids.assign(entries.size(), 0);
  std::vector<int> cursor(offsets.begin(), offsets.end() - 1);
  for (const auto& [row, id] : entries) ids[cursor[row]++] = id;
}

bool joined_by_a_spring(const SpringModel& model, int p, int q) {
  const ParticleSpringIncidence& incidence = model.incidence;
  for (int e = incidence.offsets[p]; e < incidence.offsets[p + 1]; ++e) {
    const int s = incidence.springs[e];
    if (model.springs(s, incidence.first_end[e] ? 1 : 0) == q) return true;
  }
  return false;
}

void build_coupling_incidence(SpringModel& model) {
  std::vector<std::pair<int, int>> by_spring, by_particle;
  for (int c = 0; c < static_cast<int>(model.couplings.rows()); ++c) {
    // the Jacobian's cross blocks join the ends of the two springs: they need a spring there
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        const int p = model.springs(model.couplings(c, 0), i);
        const int q = model.springs(model.couplings(c, 1), j);
        if (p != q && !joined_by_a_spring(model, p, q)) {
          fail("coupling " + std::to_string(c) + " joins springs whose ends " + std::to_string(p) +
               " and " + std::to_string(q) + " share no spring, expected two edges of a triangle");
        }
      }
    }
    int ends[4];
    for (int k = 0; k < 2; ++k) {
      const int spring = model.couplings(c, k);
      by_spring.emplace_back(spring, c);
      ends[2 * k] = model.springs(spring, 0);
      ends[2 * k + 1] = model.springs(spring, 1);
    }
    std::sort(ends, ends + 4);
    for (int k = 0; k < 4; ++k) {
      if (k == 0 || ends[k] != ends[k - 1]) by_particle.emplace_back(ends[k], c);
    }
  }
  SpringCouplingIncidence& incidence = model.coupling_incidence;
  compress_rows(model.spring_count(), by_spring, incidence.spring_offsets,
                incidence.spring_couplings);
  compress_rows(model.particle_count(), by_particle, incidence.particle_offsets,
                incidence.particle_couplings);
}

/// The edges of the triangles, each once as (i < j), sorted: a counting sort by i, then each
/// i's few j sorted (a std::sort of all the corner pairs made finalize_model 2.3 % of the adaptive
/// curtain, which recompiles after most remeshing passes; 0.6 % this way).
Eigen::MatrixX2i edges_of(const Eigen::MatrixX3i& triangles, int particles) {
  std::vector<int> offsets(particles + 1, 0);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int c = 0; c < 3; ++c) {
      ++offsets[std::min(triangles(t, c), triangles(t, (c + 1) % 3)) + 1];
    }
  }
  for (int p = 0; p < particles; ++p) offsets[p + 1] += offsets[p];
  std::vector<int> larger(offsets.back());
  std::vector<int> cursor(offsets.begin(), offsets.end() - 1);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int a = triangles(t, c), b = triangles(t, (c + 1) % 3);
      larger[cursor[std::min(a, b)]++] = std::max(a, b);
    }
  }
  std::vector<std::pair<int, int>> edges;
  edges.reserve(larger.size() / 2 + 1);
  for (int a = 0; a < particles; ++a) {
    const auto begin = larger.begin() + offsets[a], end = larger.begin() + offsets[a + 1];
    std::sort(begin, end);
    for (auto b = begin; b != end; ++b) {
      if (b == begin || *b != *(b - 1)) edges.emplace_back(a, *b);
    }
  }
  Eigen::MatrixX2i out(edges.size(), 2);
  for (std::size_t e = 0; e < edges.size(); ++e) out.row(e) << edges[e].first, edges[e].second;
  return out;
}

}  // namespace

void finalize_model(SpringModel& model) {
  check_sizes(model);
  check_values(model);
  model.surface_edges = edges_of(model.triangles, model.particle_count());
  const int particles = model.particle_count();
  const int springs = model.spring_count();

  model.inverse_mass.resize(particles);
  for (int p = 0; p < particles; ++p) {
    model.inverse_mass[p] = model.pinned[p] ? 0.0 : 1.0 / model.mass[p];
  }

  // counting sort of the 2 #S spring ends by particle; springs stay ascending within a row
  ParticleSpringIncidence& incidence = model.incidence;
  incidence.offsets.assign(particles + 1, 0);
  for (int s = 0; s < springs; ++s) {
    ++incidence.offsets[model.springs(s, 0) + 1];
    ++incidence.offsets[model.springs(s, 1) + 1];
  }
  for (int p = 0; p < particles; ++p) incidence.offsets[p + 1] += incidence.offsets[p];
  incidence.springs.assign(2 * springs, 0);
  incidence.first_end.assign(2 * springs, 0);
  std::vector<int> cursor(incidence.offsets.begin(), incidence.offsets.end() - 1);
  for (int s = 0; s < springs; ++s) {
    for (int end = 0; end < 2; ++end) {
      const int entry = cursor[model.springs(s, end)]++;
      incidence.springs[entry] = s;
      incidence.first_end[entry] = end == 0 ? 1 : 0;
    }
  }
  build_coupling_incidence(model);
  model.identity = next_model_identity();
}

}  // namespace tissu
