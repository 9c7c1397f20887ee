// Element stiffnesses of each material formulation against hand-computed values, and
// Delingette's linearised springs and couplings against the plane-stress membrane they claim.

#include "topology/membrane_stiffness.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace tissu {
namespace {

/// E = 1 MPa, h = 1 mm, so E h = 1000 N/m.
Material material(StiffnessFormulation formulation, double nu) {
  Material m;
  m.youngs_modulus_pa = 1e6;
  m.poisson_ratio = nu;
  m.thickness_m = 1e-3;
  m.density_kg_per_m3 = 200.0;
  m.formulation = formulation;
  return m;
}

const std::array<double, 3> right_isosceles = {1.0, 1.0, std::sqrt(2.0)};  // legs, hypotenuse

TEST(MembraneStiffness, Delingette2008OnARightIsoscelesTriangleMatchesHandValues) {
  const TriangleStiffness s =
      triangle_stiffness(material(StiffnessFormulation::delingette2008, 0.3), right_isosceles);
  // legs, opposite 45 degrees: E h (3 - nu) / (4 (1 - nu^2)) = 1000 x 2.7 / 3.64
  EXPECT_NEAR(s.edge_n_per_m[0], 741.758241758, 1e-6);
  EXPECT_NEAR(s.edge_n_per_m[1], 741.758241758, 1e-6);
  // hypotenuse, opposite 90 degrees: E h / (2 (1 + nu)) = 1000 / 2.6
  EXPECT_NEAR(s.edge_n_per_m[2], 384.615384615, 1e-6);
  // legs together (k = 2): 2 L0 L1 E h (2 + nu - 1) / (16 (1 - nu^2) A) = 2 x 1300 / 7.28
  EXPECT_NEAR(s.coupling_n_per_m[2], 357.142857143, 1e-6);
  // a leg with the hypotenuse: 2 sqrt(2) E h (nu - 1) / 7.28 (cot 90 degrees = 0)
  EXPECT_NEAR(s.coupling_n_per_m[0], -271.964146610, 1e-6);
  EXPECT_NEAR(s.coupling_n_per_m[1], -271.964146610, 1e-6);
}

TEST(MembraneStiffness, VanGelder1998AndLloyd2007OnTrianglesMatchHandValues) {
  const TriangleStiffness v =
      triangle_stiffness(material(StiffnessFormulation::van_gelder1998, 1.0 / 3), right_isosceles);
  EXPECT_NEAR(v.edge_n_per_m[0], 500.0, 1e-9);  // E h A / L^2 = 1000 x 0.5 / 1
  EXPECT_NEAR(v.edge_n_per_m[2], 250.0, 1e-9);  // 1000 x 0.5 / 2
  const TriangleStiffness l =
      triangle_stiffness(material(StiffnessFormulation::lloyd2007, 1.0 / 3), right_isosceles);
  for (double k : l.edge_n_per_m) EXPECT_NEAR(k, 433.012701892, 1e-6);  // sqrt(3)/4 E h
  for (double c : v.coupling_n_per_m) EXPECT_EQ(c, 0.0);
}

TEST(MembraneStiffness, RectangleFormulationsOnAUnitSquareMatchHandValues) {
  const RectangleStiffness lloyd =
      rectangle_stiffness(material(StiffnessFormulation::lloyd2007, 1.0 / 3), 1.0, 1.0);
  EXPECT_NEAR(lloyd.side_a_n_per_m, 312.5, 1e-9);    // 5/16 E h
  EXPECT_NEAR(lloyd.diagonal_n_per_m, 437.5, 1e-9);  // 7/16 E h
  const RectangleStiffness baudet =
      rectangle_stiffness(material(StiffnessFormulation::baudet2009, 0.3), 1.0, 1.0);
  EXPECT_NEAR(baudet.side_a_n_per_m, 365.384615385, 1e-6);  // E h 1.9 / 5.2
  EXPECT_NEAR(baudet.side_b_n_per_m, 365.384615385, 1e-6);
  EXPECT_NEAR(baudet.diagonal_n_per_m, 384.615384615, 1e-6);  // E h 2 / 5.2
  const RectangleStiffness natsupakpong =
      rectangle_stiffness(material(StiffnessFormulation::natsupakpong2010, 0.3), 1.0, 1.0);
  // lambda = E nu / (1 - nu^2) = 329,670 Pa, mu = E / (2 (1 + nu)) = 384,615 Pa
  EXPECT_NEAR(natsupakpong.side_a_n_per_m, 302.197802198, 1e-6);    // h (lambda/3 + mu/2)
  EXPECT_NEAR(natsupakpong.diagonal_n_per_m, 425.824175824, 1e-6);  // h (5 lambda/12 + 3 mu/4)
}

TEST(MembraneStiffness, BaudetOnARectangleGivesEachSideItsOwnStiffness) {
  const RectangleStiffness s =
      rectangle_stiffness(material(StiffnessFormulation::baudet2009, 0.25), 2.0, 1.5);
  const double scale = 1000.0 / (4.0 * 2.0 * 1.5 * 1.25);
  EXPECT_NEAR(s.side_a_n_per_m, scale * (1.5 * 1.5 * 2.75 - 4.0), 1e-9);
  EXPECT_NEAR(s.side_b_n_per_m, scale * (4.0 * 2.75 - 1.5 * 1.5), 1e-9);
  EXPECT_NEAR(s.diagonal_n_per_m, scale * 6.25, 1e-9);
}

/// Plane-stress linear membrane energy of a triangle under small nodal displacements u (m):
/// h A (mu eps:eps + lambda/2 tr(eps)^2), eps = sym(grad u), the linear FEM element (CST).
double membrane_energy_j(const Material& m, const std::array<Eigen::Vector2d, 3>& x,
                         const std::array<Eigen::Vector2d, 3>& u) {
  Eigen::Matrix2d rest;
  rest << x[1] - x[0], x[2] - x[0];
  Eigen::Matrix2d moved;
  moved << u[1] - u[0], u[2] - u[0];
  const Eigen::Matrix2d grad = moved * rest.inverse();
  const Eigen::Matrix2d eps = 0.5 * (grad + grad.transpose());
  const double nu = m.poisson_ratio, e = m.youngs_modulus_pa;
  const double lambda = e * nu / (1 - nu * nu), mu = e / (2 * (1 + nu));
  const double area = 0.5 * std::abs(rest.determinant());
  return m.thickness_m * area *
         (mu * eps.cwiseProduct(eps).sum() + 0.5 * lambda * eps.trace() * eps.trace());
}

TEST(MembraneStiffness, DelingetteSpringsWithCouplingsAreTheLinearMembraneOnAnyTriangle) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (double nu : {0.0, 0.2, 0.3, 0.45, -0.5}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::array<Eigen::Vector2d, 3> x, u;
      for (auto& p : x) p = {coordinate(rng), coordinate(rng)};
      Eigen::Matrix2d rest;
      rest << x[1] - x[0], x[2] - x[0];
      if (std::abs(rest.determinant()) < 0.1) continue;  // skip slivers
      for (auto& d : u) d = {coordinate(rng), coordinate(rng)};
      const Material m = material(StiffnessFormulation::delingette2008, nu);
      // edge k joins vertices k+1 and k+2
      std::array<double, 3> lengths{}, stretch{};
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2d edge = x[(k + 2) % 3] - x[(k + 1) % 3];
        lengths[k] = edge.norm();
        stretch[k] = (u[(k + 2) % 3] - u[(k + 1) % 3]).dot(edge) / lengths[k];  // linearised dl
      }
      const TriangleStiffness s = triangle_stiffness(m, lengths);
      double springs_j = 0.0;
      for (int k = 0; k < 3; ++k) {
        springs_j += 0.5 * s.edge_n_per_m[k] * stretch[k] * stretch[k] +
                     s.coupling_n_per_m[k] * stretch[(k + 1) % 3] * stretch[(k + 2) % 3];
      }
      const double expected_j = membrane_energy_j(m, x, u);
      EXPECT_NEAR(springs_j, expected_j, 1e-9 * expected_j) << "nu " << nu << ", trial " << trial;
    }
  }
}

TEST(MembraneStiffness, PoissonRangesAndNamesAreWhatMessagesSay) {
  EXPECT_EQ(describe(supported_poisson_ratios(StiffnessFormulation::lloyd2007)), "1/3");
  EXPECT_EQ(describe(supported_poisson_ratios(StiffnessFormulation::delingette2008)), "(-1, 0.5)");
  EXPECT_EQ(describe(supported_poisson_ratios(StiffnessFormulation::baudet2009)), "(-1/3, 0.5)");
  EXPECT_TRUE(supported_poisson_ratios(StiffnessFormulation::van_gelder1998).contains(1.0 / 3));
  EXPECT_FALSE(supported_poisson_ratios(StiffnessFormulation::van_gelder1998).contains(0.3));
  EXPECT_FALSE(supported_poisson_ratios(StiffnessFormulation::delingette2008).contains(0.5));
  for (int f = 0; f < stiffness_formulation_count; ++f) {
    const auto formulation = static_cast<StiffnessFormulation>(f);
    EXPECT_EQ(stiffness_formulation_from_string(to_string(formulation)), formulation);
  }
  EXPECT_FALSE(stiffness_formulation_from_string("delingette").has_value());
}

TEST(MembraneStiffness, BendingSpringStoresThePlateEnergyAtANinetyDegreeFold) {
  const Material m = material(StiffnessFormulation::delingette2008, 0.3);
  // two right isosceles triangles (legs 0.1 m) sharing their hypotenuse p q
  const Eigen::Vector3d p(0, 0, 0), q(0.1, 0.1, 0), a(0.1, 0, 0), b(0, 0.1, 0);
  const double area = 0.005;
  const double k = bending_spring_stiffness(m, p, q, a, b, area, 3, area, 3);
  // plate: D/2 (theta/delta)^2 A_hinge, delta = 2 x (1/3 of the apex height 0.0707 m: the
  // centroids), A_hinge = 2 x area/3; D = E h^3 / (12 (1 - nu^2))
  const double d = 1e6 * 1e-9 / (12 * 0.91);
  const double delta = 2 * (0.1 / std::sqrt(2.0)) / 3.0;
  const double theta = M_PI / 2;
  const double plate_j = 0.5 * d * (theta / delta) * (theta / delta) * (2 * area / 3);
  // folded by 90 degrees the apices are both 0.0707 m from the hinge, at right angles: their
  // distance drops from 0.1414 m to 0.1 m
  const double shortening = 0.1 * std::sqrt(2.0) - 0.1;
  EXPECT_NEAR(0.5 * k * shortening * shortening, plate_j, 1e-12 * plate_j);
  // the same hinge 10 times larger: D unchanged, so k scales as 1 / size^2
  const double k_large =
      bending_spring_stiffness(m, 10 * p, 10 * q, 10 * a, 10 * b, 100 * area, 3, 100 * area, 3);
  EXPECT_NEAR(k_large, k / 100, 1e-9 * k);
}

}  // namespace
}  // namespace tissu
