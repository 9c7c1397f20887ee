#pragma once
/// \file
/// Spring stiffnesses of one cell from its rest geometry and a Material, one pure function per
/// kind of cell, following the formulation named in the material (material.hpp). A spring's
/// stiffness is the sum of what each cell it lies in gives it: an interior edge gets the share of
/// both its faces, a boundary edge one. Linear (Hookean) springs: energy k/2 (l - l0)^2. CGAL-free.

#include <Eigen/Core>
#include <array>

#include "topology/material.hpp"

namespace tissu {

/// What one triangle gives its springs. Edge k is opposite vertex k (it joins k+1 and k+2).
struct TriangleStiffness {
  std::array<double, 3> edge_n_per_m{};  ///< stiffness of the spring along edge k (N/m)
  /// Coupling between the stretches of edges k+1 and k+2: energy C (l_{k+1} - L_{k+1})
  /// (l_{k+2} - L_{k+2}) (N/m). Only delingette2008 has it; the solver applies it as a
  /// SpringModel coupling (solver/forces/spring_coupling.hpp).
  std::array<double, 3> coupling_n_per_m{};
};

/// What one rectangle with sides a (edges 0 and 2) and b (edges 1 and 3) gives its springs.
struct RectangleStiffness {
  double side_a_n_per_m = 0.0;    ///< each of the two edges of length a (N/m)
  double side_b_n_per_m = 0.0;    ///< each of the two edges of length b (N/m)
  double diagonal_n_per_m = 0.0;  ///< each of the two diagonals (N/m)
};

/// The triangle's share for `material.formulation`, from its rest edge lengths L_k (m). The
/// formulation must be defined on triangles (formulation_cells()) and the triangle not degenerate.
TriangleStiffness triangle_stiffness(const Material& material,
                                     const std::array<double, 3>& rest_edge_lengths_m);

/// The rectangle's share for `material.formulation`, from its rest sides a, b (m). The formulation
/// must be defined on rectangles (formulation_cells()).
RectangleStiffness rectangle_stiffness(const Material& material, double side_a_m, double side_b_m);

/// Stiffness (N/m) of the bending spring across a hinge, from the rest positions (m) of the
/// hinge's ends p, q and of the spring's ends a, b (one in each face), and the rest areas (m^2)
/// and corner counts of the two faces. The scaling rule (docs/materials.md): a plate of bending
/// modulus D = E h^3 / (12 (1 - nu^2)) folded along the hinge by theta stores
///   W_plate(theta) = D/2 (theta / delta)^2 A_hinge,
/// delta the distance between the two faces' centroids across the hinge (the length over which
/// theta is the turned angle) and A_hinge each face's area over its corner count, summed. A spring
/// changes length only at second order in theta, so its energy grows as theta^4: the rule makes
/// the spring's energy equal W_plate at a fold of 90 degrees.
double bending_spring_stiffness(const Material& material, const Eigen::Vector3d& p,
                                const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& b, double area_a_m2, int corners_a,
                                double area_b_m2, int corners_b);

}  // namespace tissu
