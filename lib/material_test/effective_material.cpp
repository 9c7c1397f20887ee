#include "lib/material_test/effective_material.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "solver/forces/force_jacobian.hpp"
#include "topology/cloth_properties.hpp"
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
  // border particles: the ends of free darts
  std::vector<bool> on_border(particles, false);
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (!lcc.is_free<2>(d)) continue;
    on_border[lcc.vertex_attribute(d)->info().particle_index] = true;
    on_border[lcc.vertex_attribute(lcc.next(d))->info().particle_index] = true;
  }
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (int p = 0; p < particles; ++p) centre += compiled.state.x.segment<2>(3 * p);
  centre /= particles;
  // degrees of freedom: free (interior) ones first, then the prescribed (border) ones
  std::vector<int> slot(2 * particles);
  int free_count = 0;
  for (int p = 0; p < particles; ++p) {
    if (!on_border[p]) slot[2 * p] = free_count++, slot[2 * p + 1] = free_count++;
  }
  int prescribed_count = 0;
  for (int p = 0; p < particles; ++p) {
    if (on_border[p]) slot[2 * p] = prescribed_count++, slot[2 * p + 1] = prescribed_count++;
  }
  const Eigen::SparseMatrix<double> k = in_plane_stiffness(compiled);
  std::vector<Eigen::Triplet<double>> interior, coupling;
  for (int column = 0; column < k.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, column); it; ++it) {
      if (on_border[it.row() / 2]) continue;
      if (on_border[it.col() / 2]) {
        coupling.emplace_back(slot[it.row()], slot[it.col()], it.value());
      } else {
        interior.emplace_back(slot[it.row()], slot[it.col()], it.value());
      }
    }
  }
  Eigen::SparseMatrix<double> k_ii(free_count, free_count), k_ib(free_count, prescribed_count);
  k_ii.setFromTriplets(interior.begin(), interior.end());
  k_ib.setFromTriplets(coupling.begin(), coupling.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  if (free_count > 0) {
    solver.compute(k_ii);
    if (solver.info() != Eigen::Success) {
      throw std::runtime_error("measure_effective_material: the spring network is not rigid");
    }
  }

  const double area_m2 = rest_area_m2(lcc);
  // stress (Voigt: xx, yy, xy) per unit strain (Voigt: xx, yy, engineering xy), column by column
  Eigen::Matrix3d c;
  for (int load = 0; load < 3; ++load) {
    Eigen::Matrix2d strain = Eigen::Matrix2d::Zero();
    if (load < 2) {
      strain(load, load) = 1.0;
    } else {
      strain(0, 1) = strain(1, 0) = 0.5;
    }
    Eigen::VectorXd u(2 * particles);
    Eigen::VectorXd u_border(prescribed_count);
    for (int p = 0; p < particles; ++p) {
      if (!on_border[p]) continue;
      const Eigen::Vector2d displacement = strain * (compiled.state.x.segment<2>(3 * p) - centre);
      u_border.segment<2>(slot[2 * p]) = displacement;
    }
    Eigen::VectorXd u_interior = Eigen::VectorXd::Zero(free_count);
    if (free_count > 0) u_interior = solver.solve(-(k_ib * u_border));
    for (int p = 0; p < particles; ++p) {
      u.segment<2>(2 * p) = on_border[p] ? Eigen::Vector2d(u_border.segment<2>(slot[2 * p]))
                                         : Eigen::Vector2d(u_interior.segment<2>(slot[2 * p]));
    }
    const Eigen::VectorXd reaction = k * u;  // force the grips apply (N)
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

}  // namespace tissu
