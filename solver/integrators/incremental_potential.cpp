#include "solver/integrators/incremental_potential.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "solver/forces/spring_coupling.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

constexpr double armijo_slope_fraction = 1e-4;  // c_1 of the sufficient decrease condition
constexpr int max_backtracks = 30;
constexpr double energy_round_off = 1e-13;  // relative: a smaller change of E is round-off

}  // namespace

void predict_step(const SpringModel& model, double time_step_s, const State& state,
                  const Eigen::VectorXd& external_force, Eigen::VectorXd& first_iterate,
                  Eigen::VectorXd& inertial) {
  const int particles = model.particle_count();
  const double h = time_step_s;
  first_iterate.resize(3 * particles);
  inertial.resize(3 * particles);
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    const Eigen::Vector3d moved = state.x.segment<3>(3 * p) + h * state.v.segment<3>(3 * p);
    first_iterate.segment<3>(3 * p) = moved;
    inertial.segment<3>(3 * p) =
        moved + (h * h * model.inverse_mass[p]) * external_force.segment<3>(3 * p);
  }
}

bool backtracking_line_search(const SpringModel& model, const StepPotential& potential,
                              const Eigen::VectorXd& x, const Eigen::VectorXd& gradient,
                              double energy_j, const Eigen::VectorXd& direction,
                              StepPotentialWorkspace& workspace, Eigen::VectorXd& trial_x,
                              Eigen::VectorXd& trial_gradient, double& trial_energy_j) {
  const double slope_j = gradient.dot(direction);  // dE/dalpha at alpha = 0, < 0
  double alpha = 1.0;
  for (int backtrack = 0; backtrack <= max_backtracks; ++backtrack, alpha *= 0.5) {
    trial_x = x + alpha * direction;
    trial_energy_j = evaluate_step_potential(model, potential, trial_x, workspace, &trial_gradient);
    if (trial_energy_j <= energy_j + armijo_slope_fraction * alpha * slope_j +
                              energy_round_off * std::abs(energy_j)) {
      return true;
    }
  }
  return false;
}

void prepare_step_potential(const SpringModel& model, const StepPotential& potential,
                            StepPotentialWorkspace& workspace) {
  const int springs = model.spring_count();
  const Eigen::VectorXd& x_n = *potential.start_x;
  workspace.start_directions.resize(3, springs);
  workspace.start_projections_m.resize(springs);
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const Eigen::Vector3d d =
        x_n.segment<3>(3 * model.springs(s, 0)) - x_n.segment<3>(3 * model.springs(s, 1));
    const double length_m = d.norm();
    const Eigen::Vector3d u_n =
        length_m < spring_length_epsilon ? Eigen::Vector3d::Zero() : Eigen::Vector3d(d / length_m);
    workspace.start_directions.col(s) = u_n;
    workspace.start_projections_m[s] = u_n.dot(d);
  }
}

double evaluate_step_potential(const SpringModel& model, const StepPotential& potential,
                               const Eigen::VectorXd& x, StepPotentialWorkspace& workspace,
                               Eigen::VectorXd* gradient) {
  const int particles = model.particle_count();
  const int springs = model.spring_count();
  const double h = potential.time_step_s;
  const Eigen::VectorXd& x_n = *potential.start_x;
  const Eigen::VectorXd& y = *potential.inertial;
  assert(workspace.start_directions.cols() == springs && "call prepare_step_potential() first");
  const bool coupled = model.couplings.rows() > 0;
  if (coupled) {
    spring_coupling_tensions(model, x, workspace.spring_stretch, workspace.coupling_tension);
  }
  workspace.spring_energy_j.resize(springs);
  workspace.spring_forces.resize(3, springs);
  const double viscous_scale = 1.0 / h;  // nu/h (N/m per N s/m)

#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const int i = model.springs(s, 0);
    const int j = model.springs(s, 1);
    const Eigen::Vector3d d = x.segment<3>(3 * i) - x.segment<3>(3 * j);
    const double length_m = d.norm();
    const double stretch_m = length_m - model.rest_length[s];
    double energy_j = 0.5 * model.stiffness[s] * stretch_m * stretch_m;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    if (length_m >= spring_length_epsilon) {
      // elastic -k (|d| - l) u, plus the couplings' extra tension T: -T u
      double tension_n = model.stiffness[s] * stretch_m;
      if (coupled) tension_n += workspace.coupling_tension[s];
      force = (-tension_n / length_m) * d;
    }
    // viscous along the start direction: -nu/h ((d - d_n) . u_n) u_n
    const auto u_n = workspace.start_directions.col(s);
    const double rate = u_n.dot(d) - workspace.start_projections_m[s];  // (d - d_n) . u_n (m)
    const double viscous = viscous_scale * model.damping[s];
    energy_j += 0.5 * viscous * rate * rate;
    force -= (viscous * rate) * u_n;
    workspace.spring_energy_j[s] = energy_j;
    workspace.spring_forces.col(s) = force;
  }

  const double inertia_per_kg = 1.0 / (h * h);          // 1/h^2 (1/s^2)
  const double air_per_kg = potential.air_damping / h;  // c/h (1/s^2)
  double particle_energy_j = 0.0;
  for (int p = 0; p < particles; ++p) {  // serial: a fixed summation order
    if (model.inverse_mass[p] == 0.0) continue;
    particle_energy_j +=
        0.5 * model.mass[p] *
        (inertia_per_kg * (x.segment<3>(3 * p) - y.segment<3>(3 * p)).squaredNorm() +
         air_per_kg * (x.segment<3>(3 * p) - x_n.segment<3>(3 * p)).squaredNorm());
  }
  double energy_j = particle_energy_j + workspace.spring_energy_j.sum();
  if (coupled) {
    for (Eigen::Index c = 0; c < model.couplings.rows(); ++c) {
      energy_j += model.coupling_stiffness[c] * workspace.spring_stretch[model.couplings(c, 0)] *
                  workspace.spring_stretch[model.couplings(c, 1)];
    }
  }
  if (gradient == nullptr) {
    if (potential.contacts != nullptr)
      energy_j += add_contact_potential(*potential.contacts, x, nullptr);
    return energy_j;
  }

  const ParticleSpringIncidence& incidence = model.incidence;
  gradient->resize(3 * particles);
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (model.inverse_mass[p] == 0.0) {
      gradient->segment<3>(3 * p).setZero();
      continue;
    }
    Eigen::Vector3d g =
        model.mass[p] * (inertia_per_kg * (x.segment<3>(3 * p) - y.segment<3>(3 * p)) +
                         air_per_kg * (x.segment<3>(3 * p) - x_n.segment<3>(3 * p)));
    for (int e = incidence.offsets[p]; e < incidence.offsets[p + 1]; ++e) {
      const auto force = workspace.spring_forces.col(incidence.springs[e]);
      if (incidence.first_end[e]) {
        g -= force;
      } else {
        g += force;
      }
    }
    gradient->segment<3>(3 * p) = g;
  }
  if (potential.contacts != nullptr)
    energy_j += add_contact_potential(*potential.contacts, x, gradient);
  return energy_j;
}

double relative_correction(const SpringModel& model, double time_step_s,
                           const Eigen::VectorXd& correction, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& start_x, const Eigen::VectorXd& external_force,
                           double external_fraction) {
  const double h2 = time_step_s * time_step_s;
  double correction2 = 0.0, displacement2 = 0.0, external2 = 0.0;  // squared maxima (m^2)
  for (int p = 0; p < model.particle_count(); ++p) {
    if (model.inverse_mass[p] == 0.0) continue;
    correction2 = std::max(correction2, correction.segment<3>(3 * p).squaredNorm());
    displacement2 =
        std::max(displacement2, (x.segment<3>(3 * p) - start_x.segment<3>(3 * p)).squaredNorm());
    external2 = std::max(external2, (external_fraction * h2 * model.inverse_mass[p] *
                                     external_force.segment<3>(3 * p))
                                        .squaredNorm());
  }
  const double floor_m = spring_length_epsilon;
  const double scale2 = std::max({displacement2, external2, floor_m * floor_m});
  return std::sqrt(correction2 / scale2);
}

double step_force_scale(const SpringModel& model, const StepPotential& potential) {
  const double inertia_per_kg = 1.0 / (potential.time_step_s * potential.time_step_s);
  double squared_n2 = 0.0;
  for (int p = 0; p < model.particle_count(); ++p) {
    if (model.inverse_mass[p] == 0.0) continue;
    squared_n2 += (model.mass[p] * inertia_per_kg *
                   (potential.inertial->segment<3>(3 * p) - potential.start_x->segment<3>(3 * p)))
                      .squaredNorm();
  }
  return std::sqrt(squared_n2);
}

double relative_residual(double gradient_norm_n, double force_scale_n,
                         double first_gradient_norm_n) {
  const double scale_n = force_scale_n > 0.0 ? force_scale_n : first_gradient_norm_n;
  if (scale_n == 0.0) return gradient_norm_n == 0.0 ? 0.0 : 1.0;
  return gradient_norm_n / scale_n;
}

}  // namespace tissu
