#include "topology/membrane_stiffness.hpp"

#include <Eigen/Geometry>
#include <cassert>
#include <cmath>

namespace tissu {
namespace {

constexpr double pi = 3.14159265358979323846;

/// Rest area from the three edge lengths (Heron's formula in its stable form, Kahan 2014).
double triangle_area_m2(const std::array<double, 3>& lengths_m) {
  double a = lengths_m[0], b = lengths_m[1], c = lengths_m[2];
  if (a < b) std::swap(a, b);
  if (a < c) std::swap(a, c);
  if (b < c) std::swap(b, c);
  const double product = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return 0.25 * std::sqrt(std::max(product, 0.0));
}

/// cot of the angle opposite edge k: (L_{k+1}^2 + L_{k+2}^2 - L_k^2) / (4 A).
double cot_opposite(const std::array<double, 3>& lengths_m, int k, double area_m2) {
  const double lk = lengths_m[k], l1 = lengths_m[(k + 1) % 3], l2 = lengths_m[(k + 2) % 3];
  return (l1 * l1 + l2 * l2 - lk * lk) / (4.0 * area_m2);
}

/// Delingette 2008, "Triangular springs for modeling nonlinear membranes", IEEE TVCG 14(2),
/// section V: the St Venant-Kirchhoff energy of a triangle written with S_k = l_k^2 - L_k^2 is
///   W = sum_k k_k/4 S_k^2 + sum_k c_k/2 S_{k+1} S_{k+2},
///   k_k = E h (2 cot^2 a_k + 1 - nu) / (16 (1 - nu^2) A),
///   c_k = E h (2 cot a_{k+1} cot a_{k+2} + nu - 1) / (16 (1 - nu^2) A),
/// a_k the rest angle opposite edge k, A the rest area (the course's table; checked against the
/// St Venant-Kirchhoff energy in membrane_stiffness_test). For small strains S_k = 2 L_k dl_k, so
/// the biquadratic spring is a Hookean spring 2 k_k L_k^2 and the coupling 2 c_k L_{k+1} L_{k+2}.
TriangleStiffness delingette2008(const Material& m, const std::array<double, 3>& lengths_m) {
  const double area_m2 = triangle_area_m2(lengths_m);
  const double nu = m.poisson_ratio;
  const double scale = m.youngs_modulus_pa * m.thickness_m / (16.0 * (1.0 - nu * nu) * area_m2);
  std::array<double, 3> cot{};
  for (int k = 0; k < 3; ++k) cot[k] = cot_opposite(lengths_m, k, area_m2);
  TriangleStiffness out;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double biquadratic = scale * (2.0 * cot[k] * cot[k] + 1.0 - nu);
    const double angular = scale * (2.0 * cot[i] * cot[j] + nu - 1.0);
    out.edge_n_per_m[k] = 2.0 * biquadratic * lengths_m[k] * lengths_m[k];
    out.coupling_n_per_m[k] = 2.0 * angular * lengths_m[i] * lengths_m[j];
  }
  return out;
}

/// Van Gelder 1998, "Approximate simulation of elastic membranes by triangulated spring meshes",
/// J. Graphics Tools 3(2): k = E h sum over the edge's triangles of A_e / l0^2; one triangle's
/// share is E h A / L_k^2.
TriangleStiffness van_gelder1998(const Material& m, const std::array<double, 3>& lengths_m) {
  const double area_m2 = triangle_area_m2(lengths_m);
  TriangleStiffness out;
  for (int k = 0; k < 3; ++k) {
    out.edge_n_per_m[k] =
        m.youngs_modulus_pa * m.thickness_m * area_m2 / (lengths_m[k] * lengths_m[k]);
  }
  return out;
}

/// Lloyd, Szekely & Harders 2007, "Identification of spring parameters for deformable object
/// simulation", IEEE TVCG 13(5): k = sqrt(3)/4 E h per triangle of the edge (derived on
/// equilateral triangles).
TriangleStiffness lloyd2007_triangle(const Material& m) {
  TriangleStiffness out;
  out.edge_n_per_m.fill(std::sqrt(3.0) / 4.0 * m.youngs_modulus_pa * m.thickness_m);
  return out;
}

/// Lloyd et al. 2007 on rectangles: 5/16 E h per rectangle of an edge, 7/16 E h per diagonal.
RectangleStiffness lloyd2007_rectangle(const Material& m) {
  const double eh = m.youngs_modulus_pa * m.thickness_m;
  return {5.0 / 16.0 * eh, 5.0 / 16.0 * eh, 7.0 / 16.0 * eh};
}

/// Baudet et al. 2009, "Integrating tensile parameters in mass-spring system for deformable
/// object simulation" (the course's table): for a rectangle l0 x h0, the edge of length i (the
/// other side j) gets E h (j^2 (3 nu + 2) - i^2) / (4 l0 h0 (1 + nu)) and each diagonal
/// E h (l0^2 + h0^2) / (4 l0 h0 (1 + nu)).
RectangleStiffness baudet2009(const Material& m, double a_m, double b_m) {
  const double nu = m.poisson_ratio;
  const double scale = m.youngs_modulus_pa * m.thickness_m / (4.0 * a_m * b_m * (1.0 + nu));
  return {scale * (b_m * b_m * (3.0 * nu + 2.0) - a_m * a_m),
          scale * (a_m * a_m * (3.0 * nu + 2.0) - b_m * b_m), scale * (a_m * a_m + b_m * b_m)};
}

/// Natsupakpong & Cavusoglu 2010, "Determination of elasticity parameters in lumped element
/// (mass-spring) models of deformable objects", Graphical Models 72(6) (the course's table): edges
/// h (lambda/3 + mu/2), diagonals h (5 lambda/12 + 3 mu/4), with the plane-stress Lame constants
/// lambda = E nu / (1 - nu^2), mu = E / (2 (1 + nu)).
RectangleStiffness natsupakpong2010(const Material& m) {
  const double nu = m.poisson_ratio;
  const double lambda = m.youngs_modulus_pa * nu / (1.0 - nu * nu);
  const double mu = m.youngs_modulus_pa / (2.0 * (1.0 + nu));
  const double edge = m.thickness_m * (lambda / 3.0 + mu / 2.0);
  return {edge, edge, m.thickness_m * (5.0 * lambda / 12.0 + 3.0 * mu / 4.0)};
}

/// Distance between a face's centroid and its edge of length e (m): height h = A/e over 3 for a
/// triangle, over 2 for a rectangle.
double centroid_distance_m(double area_m2, int corners, double edge_m) {
  return area_m2 / edge_m * (corners == 3 ? 2.0 / 3.0 : 0.5);
}

}  // namespace

TriangleStiffness triangle_stiffness(const Material& material,
                                     const std::array<double, 3>& rest_edge_lengths_m) {
  switch (material.formulation) {
    case StiffnessFormulation::van_gelder1998:
      return van_gelder1998(material, rest_edge_lengths_m);
    case StiffnessFormulation::lloyd2007:
      return lloyd2007_triangle(material);
    case StiffnessFormulation::delingette2008:
      return delingette2008(material, rest_edge_lengths_m);
    case StiffnessFormulation::baudet2009:
    case StiffnessFormulation::natsupakpong2010:
      break;
  }
  assert(false && "formulation not defined on triangles");
  return {};
}

RectangleStiffness rectangle_stiffness(const Material& material, double side_a_m, double side_b_m) {
  switch (material.formulation) {
    case StiffnessFormulation::lloyd2007:
      return lloyd2007_rectangle(material);
    case StiffnessFormulation::baudet2009:
      return baudet2009(material, side_a_m, side_b_m);
    case StiffnessFormulation::natsupakpong2010:
      return natsupakpong2010(material);
    case StiffnessFormulation::van_gelder1998:
    case StiffnessFormulation::delingette2008:
      break;
  }
  assert(false && "formulation not defined on rectangles");
  return {};
}

double bending_spring_stiffness(const Material& material, const Eigen::Vector3d& p,
                                const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& b, double area_a_m2, int corners_a,
                                double area_b_m2, int corners_b) {
  const double fold_rad = 0.5 * pi;
  const double hinge_m = (q - p).norm();
  const double delta_m = centroid_distance_m(area_a_m2, corners_a, hinge_m) +
                         centroid_distance_m(area_b_m2, corners_b, hinge_m);
  const double hinge_area_m2 = area_a_m2 / corners_a + area_b_m2 / corners_b;
  const double turned = fold_rad / delta_m;
  const double plate_energy_j =
      0.5 * material.bending_modulus_n_m() * turned * turned * hinge_area_m2;
  // b's face turned about the hinge line by the fold angle
  const Eigen::AngleAxisd fold(fold_rad, (q - p) / hinge_m);
  const Eigen::Vector3d b_folded = p + fold * (b - p);
  const double shortening_m = (a - b).norm() - (a - b_folded).norm();
  return 2.0 * plate_energy_j / (shortening_m * shortening_m);
}

}  // namespace tissu
