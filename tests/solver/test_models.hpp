#pragma once
/// \file
/// Small models shared by the solver tests.

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "solver/collision/obstacle.hpp"
#include "solver/spring_model.hpp"
#include "solver/step.hpp"
#include "tests/test_thread_count.hpp"

namespace tissu::test {

/// `count` free particles of 10 g each, with no spring between them.
inline SpringModel free_particles(int count) {
  SpringModel model;
  model.mass = Eigen::VectorXd::Constant(count, 0.01);
  model.pinned.assign(count, 0);
  model.springs.resize(0, 2);
  finalize_model(model);
  return model;
}

/// One free particle of 10 g at `x`, moving at `v`.
inline SpringModel lone_particle(const Eigen::Vector3d& x, const Eigen::Vector3d& v, State& state) {
  SpringModel model = free_particles(1);
  state.x = x;
  state.v = v;
  return model;
}

/// A plane through the origin tilted by `slope_rad` about x, rising towards +y, with friction
/// coefficients mu_s and mu_k.
inline Obstacle slope(double slope_rad, double mu_static, double mu_kinetic) {
  Obstacle plane;
  plane.normal = Eigen::Vector3d(0.0, -std::sin(slope_rad), std::cos(slope_rad));
  plane.static_friction = mu_static;
  plane.kinetic_friction = mu_kinetic;
  return plane;
}

/// A mass of `mass_kg` on one spring of stiffness `stiffness_n_per_m` and rest length
/// `rest_length_m` along x, whose other end (particle 0, 1 kg) is pinned at the origin, undamped,
/// stretched by `stretch_m` and at rest. No triangles.
inline SpringModel spring_mass(double mass_kg, double stiffness_n_per_m, double rest_length_m,
                               double stretch_m, State& state) {
  SpringModel model;
  model.mass = Eigen::Vector2d(1.0, mass_kg);
  model.pinned = {1, 0};
  model.springs.resize(1, 2);
  model.springs << 0, 1;
  model.rest_length = Eigen::VectorXd::Constant(1, rest_length_m);
  model.stiffness = Eigen::VectorXd::Constant(1, stiffness_n_per_m);
  model.damping = Eigen::VectorXd::Zero(1);
  model.kind = {SpringKind::structural};
  model.triangles.resize(0, 3);
  finalize_model(model);
  state.x = Eigen::VectorXd::Zero(6);
  state.x[3] = rest_length_m + stretch_m;
  state.v = Eigen::VectorXd::Zero(6);
  return model;
}

/// `particles` particles scattered in the unit cube, `springs` springs between random distinct
/// pairs with rest lengths 0.7 to 1.3 times their current length (some stretched, some
/// compressed), random stiffness, damping and masses, and `triangles` random triangles. Fills x
/// (3#P, m) and v (3#P, m/s, random).
inline SpringModel random_model(int particles, int springs, int triangles, unsigned seed,
                                State& state) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, particles - 1);
  SpringModel model;
  state.x.resize(3 * particles);
  state.v.resize(3 * particles);
  for (int i = 0; i < 3 * particles; ++i) {
    state.x[i] = unit(rng);
    state.v[i] = 2.0 * unit(rng) - 1.0;
  }
  model.mass.resize(particles);
  for (int p = 0; p < particles; ++p) model.mass[p] = 0.01 + 0.1 * unit(rng);
  model.pinned.assign(particles, 0);
  model.springs.resize(springs, 2);
  model.rest_length.resize(springs);
  model.stiffness.resize(springs);
  model.damping.resize(springs);
  model.kind.assign(springs, SpringKind::structural);
  for (int s = 0; s < springs; ++s) {
    const int i = pick(rng);
    int j = pick(rng);
    while (j == i) j = pick(rng);
    model.springs(s, 0) = i;
    model.springs(s, 1) = j;
    const double length = (state.x.segment<3>(3 * i) - state.x.segment<3>(3 * j)).norm();
    model.rest_length[s] = length * (0.7 + 0.6 * unit(rng));
    model.stiffness[s] = 10.0 + 90.0 * unit(rng);
    model.damping[s] = unit(rng);
  }
  model.triangles.resize(triangles, 3);
  for (int t = 0; t < triangles; ++t) {
    const int a = pick(rng);
    int b = pick(rng);
    while (b == a) b = pick(rng);
    int c = pick(rng);
    while (c == a || c == b) c = pick(rng);
    model.triangles.row(t) << a, b, c;
  }
  finalize_model(model);
  return model;
}

/// A flat nx x ny grid of particles in the z = 0 plane, `spacing` (m) apart, each of mass
/// `particle_mass` (kg), with structural springs along the grid lines, shear springs across each
/// quad and bending springs two apart, all of stiffness k (N/m), damping nu (N s/m), at rest;
/// two triangles per quad. Particle id = row * nx + column. State at rest, v = 0.
inline SpringModel grid_model(int nx, int ny, double spacing, double particle_mass, double k,
                              double nu, State& state) {
  SpringModel model;
  const int particles = nx * ny;
  const auto id = [nx](int column, int row) { return row * nx + column; };
  state.x.resize(3 * particles);
  state.v.setZero(3 * particles);
  for (int row = 0; row < ny; ++row) {
    for (int column = 0; column < nx; ++column) {
      state.x.segment<3>(3 * id(column, row)) << column * spacing, row * spacing, 0.0;
    }
  }
  model.mass.setConstant(particles, particle_mass);
  model.pinned.assign(particles, 0);
  std::vector<std::pair<int, int>> pairs;
  std::vector<SpringKind> kinds;
  const auto add = [&](int a, int b, SpringKind kind) {
    pairs.emplace_back(a, b);
    kinds.push_back(kind);
  };
  std::vector<Eigen::Vector3i> triangles;
  for (int row = 0; row < ny; ++row) {
    for (int column = 0; column < nx; ++column) {
      if (column + 1 < nx) add(id(column, row), id(column + 1, row), SpringKind::structural);
      if (row + 1 < ny) add(id(column, row), id(column, row + 1), SpringKind::structural);
      if (column + 1 < nx && row + 1 < ny) {
        add(id(column, row), id(column + 1, row + 1), SpringKind::shear);
        add(id(column + 1, row), id(column, row + 1), SpringKind::shear);
        triangles.emplace_back(id(column, row), id(column + 1, row), id(column + 1, row + 1));
        triangles.emplace_back(id(column, row), id(column + 1, row + 1), id(column, row + 1));
      }
      if (column + 2 < nx) add(id(column, row), id(column + 2, row), SpringKind::bending);
      if (row + 2 < ny) add(id(column, row), id(column, row + 2), SpringKind::bending);
    }
  }
  const int springs = static_cast<int>(pairs.size());
  model.springs.resize(springs, 2);
  model.rest_length.resize(springs);
  model.stiffness.setConstant(springs, k);
  model.damping.setConstant(springs, nu);
  model.kind = kinds;
  for (int s = 0; s < springs; ++s) {
    model.springs.row(s) << pairs[s].first, pairs[s].second;
    model.rest_length[s] =
        (state.x.segment<3>(3 * pairs[s].first) - state.x.segment<3>(3 * pairs[s].second)).norm();
  }
  model.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    model.triangles.row(static_cast<Eigen::Index>(t)) = triangles[t].transpose();
  }
  finalize_model(model);
  return model;
}

/// The stiff hanging sheet of docs/benchmarks.md on n x n particles: 1 m, 1 kg, 3000 N/m springs,
/// two corners of one edge pinned; at rest in `state`.
inline SpringModel stiff_sheet(int n, State& state) {
  SpringModel model = grid_model(n, n, 1.0 / (n - 1), 1.0 / (n * n), 3000.0, 0.0, state);
  model.pinned[n * (n - 1)] = 1;
  model.pinned[n * n - 1] = 1;
  finalize_model(model);
  return model;
}

/// A vector of 3#P standard normal entries, zero on the pinned particles.
inline Eigen::VectorXd random_free_vector(const SpringModel& model, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd v(3 * model.particle_count());
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    v[i] = model.inverse_mass[i / 3] == 0.0 ? 0.0 : normal(random);
  }
  return v;
}

/// Couples every two structural or shear springs that are edges of one of the model's triangles,
/// with random stiffnesses of either sign (N/m).
inline void couple_triangle_edges(SpringModel& model, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> gamma(-300.0, 300.0);
  const auto spring_between = [&](int p, int q) {
    for (int s = 0; s < model.spring_count(); ++s) {
      if (model.kind[s] == SpringKind::bending) continue;
      if ((model.springs(s, 0) == p && model.springs(s, 1) == q) ||
          (model.springs(s, 0) == q && model.springs(s, 1) == p))
        return s;
    }
    return -1;
  };
  std::vector<std::pair<int, int>> pairs;
  for (Eigen::Index t = 0; t < model.triangles.rows(); ++t) {
    int edge[3];
    for (int k = 0; k < 3; ++k) {
      edge[k] = spring_between(model.triangles(t, k), model.triangles(t, (k + 1) % 3));
    }
    for (int k = 0; k < 3; ++k) pairs.emplace_back(edge[k], edge[(k + 1) % 3]);
  }
  model.couplings.resize(static_cast<Eigen::Index>(pairs.size()), 2);
  model.coupling_stiffness.resize(static_cast<Eigen::Index>(pairs.size()));
  for (std::size_t c = 0; c < pairs.size(); ++c) {
    model.couplings.row(c) << pairs[c].first, pairs[c].second;
    model.coupling_stiffness[c] = gamma(rng);
  }
  finalize_model(model);
}

/// `lower` and `upper` in one model (upper's particles after lower's), and their states joined
/// (velocities zero).
inline SpringModel joined_models(const SpringModel& lower, const State& lower_state,
                                 const SpringModel& upper, const State& upper_state, State& state) {
  const int offset = lower.particle_count();
  SpringModel m;
  m.mass.resize(offset + upper.particle_count());
  m.mass << lower.mass, upper.mass;
  m.pinned = lower.pinned;
  m.pinned.insert(m.pinned.end(), upper.pinned.begin(), upper.pinned.end());
  m.springs.resize(lower.spring_count() + upper.spring_count(), 2);
  m.springs << lower.springs, (upper.springs.array() + offset).matrix();
  m.rest_length.resize(m.springs.rows());
  m.rest_length << lower.rest_length, upper.rest_length;
  m.stiffness.resize(m.springs.rows());
  m.stiffness << lower.stiffness, upper.stiffness;
  m.damping.resize(m.springs.rows());
  m.damping << lower.damping, upper.damping;
  m.kind = lower.kind;
  m.kind.insert(m.kind.end(), upper.kind.begin(), upper.kind.end());
  m.triangles.resize(lower.triangles.rows() + upper.triangles.rows(), 3);
  m.triangles << lower.triangles, (upper.triangles.array() + offset).matrix();
  finalize_model(m);
  state.x.resize(lower_state.x.size() + upper_state.x.size());
  state.x << lower_state.x, upper_state.x;
  state.v = Eigen::VectorXd::Zero(state.x.size());
  return m;
}

/// Steps a copy of `initial` `steps` times with 1, then 2 OpenMP threads, each with a fresh
/// workspace; returns both end states. Restores the thread count.
inline std::array<State, 2> step_with_one_and_two_threads(const SpringModel& model,
                                                          const SolverParams& params,
                                                          const State& initial, int steps) {
  std::array<State, 2> results;
  for (int threads = 1; threads <= 2; ++threads) {
    const ScopedThreadCount count(threads);
    State& state = results[threads - 1];
    state = initial;
    StepWorkspace workspace;
    for (int n = 0; n < steps; ++n)
      EXPECT_EQ(step(model, params, state, workspace), StepStatus::ok);
  }
  return results;
}

}  // namespace tissu::test
