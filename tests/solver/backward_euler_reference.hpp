#pragma once
// A small perturbed sheet and its exact backward-Euler step, for the integrators' tests.

#include <Eigen/Dense>
#include <random>

#include "solver/forces/spring_force.hpp"
#include "solver/spring_model.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu::test {

/// A 6 x 6 sheet (0.1 m spacing, 0.01 kg particles, 100 N/m springs of damping `damping` N s/m)
/// held by two corners, positions and velocities mildly perturbed from rest by `seed`.
inline SpringModel perturbed_sheet(State& state, double damping, unsigned seed) {
  SpringModel model = grid_model(6, 6, 0.1, 0.01, 100.0, damping, state);
  model.pinned[0] = 1;
  model.pinned[5] = 1;
  finalize_model(model);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int p = 0; p < model.particle_count(); ++p) {
    if (model.pinned[p]) continue;
    for (int k = 0; k < 3; ++k) {
      state.x[3 * p + k] += 0.01 * unit(rng);
      state.v[3 * p + k] = 0.1 * unit(rng);
    }
  }
  return model;
}

// exact backward Euler by Newton's method to round-off: M (x1 - x0 - h v0) / h^2 = f(x1) + M g,
// dense, free degrees of freedom only, exact (unclamped) spring Jacobians
inline Eigen::VectorXd backward_euler_positions(const SpringModel& model, const State& state,
                                                double h, const Eigen::Vector3d& gravity) {
  const int n = model.particle_count();
  Eigen::VectorXd x1 = state.x + h * state.v;
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::VectorXd residual(3 * n);
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (int p = 0; p < n; ++p) {
      const double m = model.mass[p] / (h * h);
      residual.segment<3>(3 * p) =
          m * (x1 - state.x - h * state.v).segment<3>(3 * p) - model.mass[p] * gravity;
      jacobian.block<3, 3>(3 * p, 3 * p) += m * Eigen::Matrix3d::Identity();
    }
    for (int s = 0; s < model.spring_count(); ++s) {
      const int i = model.springs(s, 0);
      const int j = model.springs(s, 1);
      const Eigen::Vector3d xi = x1.segment<3>(3 * i);
      const Eigen::Vector3d xj = x1.segment<3>(3 * j);
      const Eigen::Vector3d f = spring_force(xi, xj, model.stiffness[s], model.rest_length[s]);
      const Eigen::Matrix3d k =
          spring_force_jacobian(xi, xj, model.stiffness[s], model.rest_length[s]);
      residual.segment<3>(3 * i) -= f;
      residual.segment<3>(3 * j) += f;
      jacobian.block<3, 3>(3 * i, 3 * i) -= k;
      jacobian.block<3, 3>(3 * j, 3 * j) -= k;
      jacobian.block<3, 3>(3 * i, 3 * j) += k;
      jacobian.block<3, 3>(3 * j, 3 * i) += k;
    }
    for (int p = 0; p < n; ++p) {
      if (!model.pinned[p]) continue;
      residual.segment<3>(3 * p).setZero();
      jacobian.middleRows(3 * p, 3).setZero();
      jacobian.middleCols(3 * p, 3).setZero();
      jacobian.block<3, 3>(3 * p, 3 * p).setIdentity();
    }
    const Eigen::VectorXd delta = jacobian.partialPivLu().solve(-residual);
    x1 += delta;
    if (delta.lpNorm<Eigen::Infinity>() < 1e-15) break;
  }
  return x1;
}

}  // namespace tissu::test
