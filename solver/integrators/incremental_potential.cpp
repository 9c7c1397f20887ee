#include "solver/integrators/incremental_potential.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "solver/forces/spring_coupling.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/parallel_sum.hpp"

namespace tissu {
namespace {

constexpr double armijo_slope_fraction = 1e-4;  // c_1 of the sufficient decrease condition
constexpr int max_backtracks = 30;
constexpr double energy_round_off = 1e-13;  // relative: a smaller change of E is round-off

/// What spring_terms() reads: flat arrays of the model, the iterate and the step's workspace.
struct SpringTermInputs {
  const int* first_ends;              ///< #S particle ids i
  const int* second_ends;             ///< #S particle ids j
  const double* x;                    ///< 3#P iterate (m)
  const double* rest_length;          ///< #S (m)
  const double* stiffness;            ///< #S (N/m)
  const double* damping;              ///< #S (N s/m), read when viscous
  const double* coupling_tension;     ///< #S (N), the couplings', read when coupled
  const double* start_directions;     ///< 3#S u_n, read when viscous
  const double* start_projections_m;  ///< #S d_n . u_n (m), read when viscous
  double viscous_scale;               ///< 1/h (1/s)
};

/// Springs [first, last): each one's energy (J) into energy_j[s - first] and force on its first
/// end (N) into force_n, in a plain loop over flat arrays that GCC vectorises: two springs a
/// register in SSE2, four in AVX2 (spring_terms_avx2()), their ends' coordinates gathered.
///   elastic: E = k/2 (|d| - l)^2, f = -(k (|d| - l) + T) d / |d|, T the couplings' tension;
///   viscous along the start direction: E = nu/(2h) r^2, f = -(nu/h) r u_n, r = (d - d_n) . u_n.
/// The viscous and coupling terms are compiled in only when the model has them: without, the loop
/// reads 24 bytes a spring instead of 72, which is what it costs on a cloth larger than the caches.
template <bool viscous, bool coupled>
__attribute__((always_inline)) inline void spring_terms(const SpringTermInputs& in, int first,
                                                        int last, double* __restrict energy_j,
                                                        double* __restrict force_n) {
#pragma omp simd
  for (int s = first; s < last; ++s) {
    const int i = in.first_ends[s], j = in.second_ends[s];
    const double dx = in.x[3 * i] - in.x[3 * j];
    const double dy = in.x[3 * i + 1] - in.x[3 * j + 1];
    const double dz = in.x[3 * i + 2] - in.x[3 * j + 2];
    const double length_m = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double stretch_m = length_m - in.rest_length[s];
    double tension_n = in.stiffness[s] * stretch_m;
    if constexpr (coupled) tension_n += in.coupling_tension[s];
    // 0 where the spring has no direction; a product, not a branch, so that the loop vectorises
    const double has_direction = length_m >= spring_length_epsilon ? 1.0 : 0.0;
    const double elastic = -has_direction * tension_n / std::max(length_m, spring_length_epsilon);
    double energy = 0.5 * in.stiffness[s] * stretch_m * stretch_m;
    double fx = elastic * dx, fy = elastic * dy, fz = elastic * dz;
    if constexpr (viscous) {
      const double ux = in.start_directions[3 * s], uy = in.start_directions[3 * s + 1],
                   uz = in.start_directions[3 * s + 2];
      const double rate_m = ux * dx + uy * dy + uz * dz - in.start_projections_m[s];
      const double viscous_n_per_m = in.viscous_scale * in.damping[s];
      energy += 0.5 * viscous_n_per_m * rate_m * rate_m;
      fx -= viscous_n_per_m * rate_m * ux;
      fy -= viscous_n_per_m * rate_m * uy;
      fz -= viscous_n_per_m * rate_m * uz;
    }
    energy_j[s - first] = energy;
    force_n[3 * s] = fx;
    force_n[3 * s + 1] = fy;
    force_n[3 * s + 2] = fz;
  }
}

/// spring_terms() in blocks whose energies stay in a buffer on the stack, added by Eigen's
/// vectorised sum; returns the springs' energy (J). (A `reduction` clause on the loop kept GCC 12
/// from vectorising it at all.)
template <bool viscous, bool coupled>
__attribute__((always_inline)) inline double summed_spring_terms(const SpringTermInputs& in,
                                                                 int first, int last,
                                                                 double* force_n) {
  constexpr int block = 256;
  double energies_j[block];
  double total_j = 0.0;
  for (int begin = first; begin < last; begin += block) {
    const int end = std::min(last, begin + block);
    spring_terms<viscous, coupled>(in, begin, end, energies_j, force_n);
    total_j += Eigen::Map<const Eigen::VectorXd>(energies_j, end - begin).sum();
  }
  return total_j;
}

using SpringTermsKernel = double (*)(const SpringTermInputs&, int, int, double*);

template <bool viscous, bool coupled>
double spring_terms_portable(const SpringTermInputs& in, int first, int last, double* force_n) {
  return summed_spring_terms<viscous, coupled>(in, first, last, force_n);
}

#if defined(__x86_64__)
template <bool viscous, bool coupled>
__attribute__((target("avx2,fma"))) double spring_terms_avx2(const SpringTermInputs& in, int first,
                                                             int last, double* force_n) {
  return summed_spring_terms<viscous, coupled>(in, first, last, force_n);
}
#endif

template <bool viscous, bool coupled>
SpringTermsKernel spring_terms_kernel(BlockProductKernel kernel) {
#if defined(__x86_64__)
  if (kernel == BlockProductKernel::avx2) return spring_terms_avx2<viscous, coupled>;
#endif
  return spring_terms_portable<viscous, coupled>;
}

SpringTermsKernel spring_terms_kernel(BlockProductKernel kernel, bool viscous, bool coupled) {
  if (viscous) {
    return coupled ? spring_terms_kernel<true, true>(kernel)
                   : spring_terms_kernel<true, false>(kernel);
  }
  return coupled ? spring_terms_kernel<false, true>(kernel)
                 : spring_terms_kernel<false, false>(kernel);
}

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
                              const Eigen::VectorXd& x, double slope_j, double energy_j,
                              const Eigen::VectorXd& direction, StepPotentialWorkspace& workspace,
                              Eigen::VectorXd& trial_x, Eigen::VectorXd& trial_gradient,
                              double& trial_energy_j) {
  const int particles = model.particle_count();
  trial_x.resize(x.size());
  double alpha = 1.0;
  for (int backtrack = 0; backtrack <= max_backtracks; ++backtrack, alpha *= 0.5) {
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
    for (int p = 0; p < particles; ++p) {
      trial_x.segment<3>(3 * p) = x.segment<3>(3 * p) + alpha * direction.segment<3>(3 * p);
    }
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
  workspace.viscous = (model.damping.array() != 0.0).any();
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

double evaluate_spring_terms(const SpringModel& model, double time_step_s, const Eigen::VectorXd& x,
                             StepPotentialWorkspace& workspace, BlockProductKernel kernel) {
  const int springs = model.spring_count();
  assert(workspace.start_directions.cols() == springs && "call prepare_step_potential() first");
  const bool coupled = model.couplings.rows() > 0;
  if (coupled)
    spring_coupling_tensions(model, x, workspace.spring_stretch, workspace.coupling_tension);
  workspace.spring_forces.resize(3, springs);
  const SpringTermInputs inputs{model.springs.col(0).data(),
                                model.springs.col(1).data(),
                                x.data(),
                                model.rest_length.data(),
                                model.stiffness.data(),
                                model.damping.data(),
                                workspace.coupling_tension.data(),
                                workspace.start_directions.data(),
                                workspace.start_projections_m.data(),
                                1.0 / time_step_s};
  auto* const terms = spring_terms_kernel(kernel, workspace.viscous, coupled);
  return chunked_sum(springs, [&](int begin, int end) {
    return terms(inputs, begin, end, workspace.spring_forces.data());
  });
}

double evaluate_step_potential(const SpringModel& model, const StepPotential& potential,
                               const Eigen::VectorXd& x, StepPotentialWorkspace& workspace,
                               Eigen::VectorXd* gradient) {
  const int particles = model.particle_count();
  const double h = potential.time_step_s;
  const Eigen::VectorXd& x_n = *potential.start_x;
  const Eigen::VectorXd& y = *potential.inertial;
  const double spring_energy_j = evaluate_spring_terms(model, h, x, workspace);

  const double inertia_per_kg = 1.0 / (h * h);          // 1/h^2 (1/s^2)
  const double air_per_kg = potential.air_damping / h;  // c/h (1/s^2)
  const ParticleSpringIncidence& incidence = model.incidence;
  if (gradient != nullptr) gradient->resize(3 * particles);
  // each free particle's inertia and air damping, and with a gradient its own: those terms' plus
  // its springs' forces, gathered in model.incidence order
  const double particle_energy_j = chunked_sum(particles, [&](int begin, int end) {
    double sum_j = 0.0;
    for (int p = begin; p < end; ++p) {
      if (model.inverse_mass[p] == 0.0) {
        if (gradient != nullptr) gradient->segment<3>(3 * p).setZero();
        continue;
      }
      const Eigen::Vector3d from_inertial_m = x.segment<3>(3 * p) - y.segment<3>(3 * p);
      const Eigen::Vector3d from_start_m = x.segment<3>(3 * p) - x_n.segment<3>(3 * p);
      sum_j += 0.5 * model.mass[p] *
               (inertia_per_kg * from_inertial_m.squaredNorm() +
                air_per_kg * from_start_m.squaredNorm());
      if (gradient == nullptr) continue;
      Eigen::Vector3d g =
          model.mass[p] * (inertia_per_kg * from_inertial_m + air_per_kg * from_start_m);
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
    return sum_j;
  });
  double energy_j = particle_energy_j + spring_energy_j;
  for (Eigen::Index c = 0; c < model.couplings.rows(); ++c) {
    energy_j += model.coupling_stiffness[c] * workspace.spring_stretch[model.couplings(c, 0)] *
                workspace.spring_stretch[model.couplings(c, 1)];
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
  const int particles = model.particle_count();
  double correction2 = 0.0, displacement2 = 0.0, external2 = 0.0;  // squared maxima (m^2)
  // clang-format off
#pragma omp parallel for reduction(max : correction2, displacement2, external2) \
    schedule(static) if (particles >= min_parallel_items)
  // clang-format on
  for (int p = 0; p < particles; ++p) {
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
