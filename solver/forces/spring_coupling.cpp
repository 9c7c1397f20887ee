#include "solver/forces/spring_coupling.hpp"

#include <algorithm>
#include <cassert>

#include "solver/forces/spring_force.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

struct SpringGeometry {
  Eigen::Vector3d u = Eigen::Vector3d::Zero();  ///< unit vector from the second end to the first
  double length_m = 0.0;
};

SpringGeometry geometry(const SpringModel& model, const Eigen::VectorXd& x, int s) {
  const Eigen::Vector3d d =
      x.segment<3>(3 * model.springs(s, 0)) - x.segment<3>(3 * model.springs(s, 1));
  SpringGeometry g;
  g.length_m = d.norm();
  if (g.length_m >= spring_length_epsilon) g.u = d / g.length_m;
  return g;
}

/// The coupling's other spring.
int other_spring(const SpringModel& model, int coupling, int spring) {
  return model.couplings(coupling, 0) == spring ? model.couplings(coupling, 1)
                                                : model.couplings(coupling, 0);
}

}  // namespace

void spring_coupling_tensions(const SpringModel& model, const Eigen::VectorXd& x,
                              Eigen::VectorXd& stretch_m, Eigen::VectorXd& tension_n) {
  const int springs = model.spring_count();
  stretch_m.resize(springs);
  tension_n.resize(springs);
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const double length_m =
        (x.segment<3>(3 * model.springs(s, 0)) - x.segment<3>(3 * model.springs(s, 1))).norm();
    stretch_m[s] = length_m - model.rest_length[s];
  }
  const SpringCouplingIncidence& incidence = model.coupling_incidence;
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    double tension = 0.0;
    for (int e = incidence.spring_offsets[s]; e < incidence.spring_offsets[s + 1]; ++e) {
      const int c = incidence.spring_couplings[e];
      tension += model.coupling_stiffness[c] * stretch_m[other_spring(model, c, s)];
    }
    tension_n[s] = tension;
  }
}

double spring_coupling_energy(const SpringModel& model, const Eigen::VectorXd& x) {
  double energy_j = 0.0;
  for (Eigen::Index c = 0; c < model.couplings.rows(); ++c) {
    const int a = model.couplings(c, 0), b = model.couplings(c, 1);
    energy_j += model.coupling_stiffness[c] *
                (geometry(model, x, a).length_m - model.rest_length[a]) *
                (geometry(model, x, b).length_m - model.rest_length[b]);
  }
  return energy_j;
}

Eigen::Matrix3d coupling_tension_jacobian(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj,
                                          double tension_n, bool clamp) {
  const Eigen::Vector3d d = xi - xj;
  const double length_m = d.norm();
  if (length_m < spring_length_epsilon) return Eigen::Matrix3d::Zero();
  const double tension = clamp ? std::max(tension_n, 0.0) : tension_n;
  const Eigen::Vector3d u = d / length_m;
  return -(tension / length_m) * (Eigen::Matrix3d::Identity() - u * u.transpose());
}

void add_coupling_velocity_products(const SpringModel& model, const Eigen::VectorXd& x,
                                    const Eigen::VectorXd& v, Eigen::Matrix3Xd& products) {
  const int springs = model.spring_count();
  const SpringCouplingIncidence& incidence = model.coupling_incidence;
#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int a = 0; a < springs; ++a) {
    if (incidence.spring_offsets[a] == incidence.spring_offsets[a + 1]) continue;
    const Eigen::Vector3d u_a = geometry(model, x, a).u;
    double rate = 0.0;  // sum of Gamma_c (rate of stretch of the other spring along its line)
    for (int e = incidence.spring_offsets[a]; e < incidence.spring_offsets[a + 1]; ++e) {
      const int c = incidence.spring_couplings[e];
      const int b = other_spring(model, c, a);
      const Eigen::Vector3d relative =
          v.segment<3>(3 * model.springs(b, 0)) - v.segment<3>(3 * model.springs(b, 1));
      rate += model.coupling_stiffness[c] * geometry(model, x, b).u.dot(relative);
    }
    products.col(a) -= rate * u_a;
  }
}

template <int StorageOrder>
void add_coupling_jacobian_blocks(const SpringModel& model, const SpringBlockPattern& pattern,
                                  const Eigen::VectorXd& x, double scale, bool filter_pinned,
                                  Eigen::SparseMatrix<double, StorageOrder>& matrix) {
  const int particles = model.particle_count();
  const SpringCouplingIncidence& incidence = model.coupling_incidence;
  double* values = matrix.valuePtr();
  const auto is_fixed = [&](int p) { return filter_pinned && model.inverse_mass[p] == 0.0; };
#pragma omp parallel for schedule(static) if (particles >= min_parallel_items)
  for (int p = 0; p < particles; ++p) {
    if (is_fixed(p)) continue;
    const int first = pattern.block_offsets[p];
    const int blocks = pattern.block_offsets[p + 1] - first;
    double* row_values = values + 9 * first;
    const auto add = [&](int q, const Eigen::Matrix3d& block) {
      if (is_fixed(q)) return;
      const auto begin = pattern.block_columns.begin() + first;
      const auto it = std::lower_bound(begin, begin + blocks, q);
      assert(it != begin + blocks && *it == q && "coupled springs' ends must share a spring");
      const int n = static_cast<int>(it - begin);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) row_values[3 * blocks * r + 3 * n + c] += block(r, c);
      }
    };
    for (int e = incidence.particle_offsets[p]; e < incidence.particle_offsets[p + 1]; ++e) {
      const int c = incidence.particle_couplings[e];
      const double gamma = scale * model.coupling_stiffness[c];
      for (int k = 0; k < 2; ++k) {  // p as an end of spring `mine`, paired with `theirs`
        const int mine = model.couplings(c, k), theirs = model.couplings(c, 1 - k);
        const int end = model.springs(mine, 0) == p ? 0 : model.springs(mine, 1) == p ? 1 : -1;
        if (end < 0) continue;
        const double sign_p = end == 0 ? 1.0 : -1.0;
        const Eigen::Matrix3d block =
            -gamma * sign_p * geometry(model, x, mine).u * geometry(model, x, theirs).u.transpose();
        add(model.springs(theirs, 0), block);
        add(model.springs(theirs, 1), -block);
      }
    }
  }
}

template void add_coupling_jacobian_blocks<Eigen::ColMajor>(
    const SpringModel&, const SpringBlockPattern&, const Eigen::VectorXd&, double, bool,
    Eigen::SparseMatrix<double, Eigen::ColMajor>&);
template void add_coupling_jacobian_blocks<Eigen::RowMajor>(
    const SpringModel&, const SpringBlockPattern&, const Eigen::VectorXd&, double, bool,
    Eigen::SparseMatrix<double, Eigen::RowMajor>&);

}  // namespace tissu
