#include "lib/material_test/effective_material.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "solver/forces/force_jacobian.hpp"
#include "topology/compile.hpp"

namespace tissu {
namespace {

/// In-plane stiffness K (2#P x 2#P, N/m) = -df/dx restricted to x and y, at the rest shape.
Eigen::SparseMatrix<double> in_plane_stiffness(const CompiledCloth& compiled) {
  ForceJacobianWorkspace workspace;
  Eigen::SparseMatrix<double> dfdx;
  force_position_jacobian(compiled.model, compiled.state.x, ForceJacobianOptions{}, workspace,
                          dfdx);
  std::vector<Eigen::Triplet<double>> entries;
  for (int column = 0; column < dfdx.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(dfdx, column); it; ++it) {
      if (it.row() % 3 == 2 || it.col() % 3 == 2) continue;
      entries.emplace_back(2 * (it.row() / 3) + it.row() % 3, 2 * (it.col() / 3) + it.col() % 3,
                           -it.value());
    }
  }
  const int n = 2 * compiled.model.particle_count();
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

/// Static equilibrium K u = f with u prescribed on some degrees of freedom and f = 0 on the
/// others: factorises the free block once, then solves for any prescribed values.
class PrescribedDisplacements {
 public:
  PrescribedDisplacements(Eigen::SparseMatrix<double> k, std::vector<bool> prescribed)
      : m_k(std::move(k)), m_prescribed(std::move(prescribed)), m_slot(m_prescribed.size()) {
    for (std::size_t dof = 0; dof < m_prescribed.size(); ++dof) {
      m_slot[dof] = m_prescribed[dof] ? m_fixed_count++ : m_free_count++;
    }
    std::vector<Eigen::Triplet<double>> free_block, coupling;
    for (int column = 0; column < m_k.outerSize(); ++column) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(m_k, column); it; ++it) {
        if (m_prescribed[it.row()]) continue;
        (m_prescribed[it.col()] ? coupling : free_block)
            .emplace_back(m_slot[it.row()], m_slot[it.col()], it.value());
      }
    }
    m_free_block.resize(m_free_count, m_free_count);
    m_free_block.setFromTriplets(free_block.begin(), free_block.end());
    m_coupling.resize(m_free_count, m_fixed_count);
    m_coupling.setFromTriplets(coupling.begin(), coupling.end());
    if (m_free_count > 0) {
      m_solver.compute(m_free_block);
      if (m_solver.info() != Eigen::Success) {
        throw std::runtime_error("material test: the spring network is not rigid");
      }
    }
  }

  /// The displacement of every degree of freedom (m) given `values` on the prescribed ones (the
  /// others ignored), and the forces K u that hold it (N): the reactions on the prescribed ones.
  void solve(const Eigen::VectorXd& values, Eigen::VectorXd& u, Eigen::VectorXd& reaction) {
    Eigen::VectorXd fixed(m_fixed_count);
    for (std::size_t dof = 0; dof < m_prescribed.size(); ++dof) {
      if (m_prescribed[dof]) fixed[m_slot[dof]] = values[dof];
    }
    Eigen::VectorXd free = Eigen::VectorXd::Zero(m_free_count);
    if (m_free_count > 0) free = m_solver.solve(-(m_coupling * fixed));
    u.resize(values.size());
    for (std::size_t dof = 0; dof < m_prescribed.size(); ++dof) {
      u[dof] = m_prescribed[dof] ? fixed[m_slot[dof]] : free[m_slot[dof]];
    }
    reaction = m_k * u;
  }

 private:
  Eigen::SparseMatrix<double> m_k;
  std::vector<bool> m_prescribed;
  std::vector<int> m_slot;
  int m_free_count = 0, m_fixed_count = 0;
  Eigen::SparseMatrix<double> m_free_block, m_coupling;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> m_solver;
};

double rest_area_m2(const ClothComplex& lcc) {
  double area = 0.0;
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    area += f->info().rest_area;
  }
  return area;
}

}  // namespace

EffectiveMaterial measure_effective_material(ClothComplex& lcc, double thickness_m) {
  const CompiledCloth compiled = compile(lcc);
  const int particles = compiled.model.particle_count();
  // border particles, the ends of free darts, have both degrees of freedom prescribed
  std::vector<bool> on_border(particles, false), prescribed(2 * particles, false);
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (!lcc.is_free<2>(d)) continue;
    for (const Dart_handle end : {Dart_handle(d), lcc.next(d)}) {
      const int p = lcc.vertex_attribute(end)->info().index_at_last_compile;
      on_border[p] = prescribed[2 * p] = prescribed[2 * p + 1] = true;
    }
  }
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (int p = 0; p < particles; ++p) centre += compiled.state.x.segment<2>(3 * p);
  centre /= particles;
  PrescribedDisplacements equilibrium(in_plane_stiffness(compiled), prescribed);

  const double area_m2 = rest_area_m2(lcc);
  // stress (Voigt: xx, yy, xy) per unit strain (Voigt: xx, yy, engineering xy), column by column
  Eigen::Matrix3d c;
  Eigen::VectorXd values(2 * particles), u, reaction;
  for (int load = 0; load < 3; ++load) {
    Eigen::Matrix2d strain = Eigen::Matrix2d::Zero();
    if (load < 2) {
      strain(load, load) = 1.0;
    } else {
      strain(0, 1) = strain(1, 0) = 0.5;
    }
    for (int p = 0; p < particles; ++p) {
      values.segment<2>(2 * p) = strain * (compiled.state.x.segment<2>(3 * p) - centre);
    }
    equilibrium.solve(values, u, reaction);  // reaction: the force the grips apply (N)
    Eigen::Matrix2d stress = Eigen::Matrix2d::Zero();
    for (int p = 0; p < particles; ++p) {
      if (!on_border[p]) continue;
      stress +=
          reaction.segment<2>(2 * p) * (compiled.state.x.segment<2>(3 * p) - centre).transpose();
    }
    stress /= area_m2 * thickness_m;
    c.col(load) << stress(0, 0), stress(1, 1), 0.5 * (stress(0, 1) + stress(1, 0));
  }

  const Eigen::Matrix3d s = c.inverse();
  const auto young = [&](const Eigen::Vector3d& d) { return 1.0 / d.dot(s * d); };
  const auto poisson = [&](const Eigen::Vector3d& d, const Eigen::Vector3d& t) {
    return -t.dot(s * d) / d.dot(s * d);
  };
  const Eigen::Vector3d warp(1, 0, 0), weft(0, 1, 0), diagonal(0.5, 0.5, 0.5),
      across(0.5, 0.5, -0.5);
  EffectiveMaterial out;
  out.e_warp_pa = young(warp);
  out.e_weft_pa = young(weft);
  out.e_diagonal_pa = young(diagonal);
  out.nu_warp = poisson(warp, weft);
  out.nu_weft = poisson(weft, warp);
  out.nu_diagonal = poisson(diagonal, across);
  out.shear_modulus_pa = c(2, 2);
  return out;
}

StripTension measure_strip_tension(ClothComplex& lcc, double thickness_m) {
  const CompiledCloth compiled = compile(lcc);
  const int particles = compiled.model.particle_count();
  const auto position = [&](int p) { return Eigen::Vector2d(compiled.state.x.segment<2>(3 * p)); };
  Eigen::Vector2d low = position(0), high = position(0);
  for (int p = 1; p < particles; ++p) {
    low = low.cwiseMin(position(p));
    high = high.cwiseMax(position(p));
  }
  const Eigen::Vector2d size = high - low;
  const double tolerance = 1e-9 * size.norm();
  const auto at = [&](double coordinate, double end) {
    return std::abs(coordinate - end) <= tolerance;
  };
  // the grips hold x on the left and right sides; one left particle is held in y too
  std::vector<bool> prescribed(2 * particles, false);
  Eigen::VectorXd values = Eigen::VectorXd::Zero(2 * particles);
  const double pull_m = 1e-3 * size.x();
  int anchor = -1;
  for (int p = 0; p < particles; ++p) {
    const bool left = at(position(p).x(), low.x()), right = at(position(p).x(), high.x());
    if (!left && !right) continue;
    prescribed[2 * p] = true;
    values[2 * p] = right ? pull_m : 0.0;
    if (left && (anchor < 0 || position(p).y() < position(anchor).y())) anchor = p;
  }
  prescribed[2 * anchor + 1] = true;
  PrescribedDisplacements equilibrium(in_plane_stiffness(compiled), prescribed);
  Eigen::VectorXd u, reaction;
  equilibrium.solve(values, u, reaction);

  double pull_force_n = 0.0, top_m = 0.0, bottom_m = 0.0;
  int top_count = 0, bottom_count = 0;
  for (int p = 0; p < particles; ++p) {
    if (at(position(p).x(), high.x())) pull_force_n += reaction[2 * p];
    if (at(position(p).y(), high.y())) top_m += u[2 * p + 1], ++top_count;
    if (at(position(p).y(), low.y())) bottom_m += u[2 * p + 1], ++bottom_count;
  }
  const double strain = pull_m / size.x();
  const double lateral_strain = (top_m / top_count - bottom_m / bottom_count) / size.y();
  StripTension out;
  out.e_pa = pull_force_n / (size.y() * thickness_m) / strain;
  out.nu = -lateral_strain / strain;
  return out;
}

}  // namespace tissu
