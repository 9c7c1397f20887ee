#pragma once
/// \file
/// The elastic constants a spring network actually has, measured the way a materials lab would
/// on a sample, but at infinitesimal strain and exactly at equilibrium.

#include "topology/cloth_complex.hpp"

namespace tissu {

/// Effective small-strain constants of a flat sheet, in its own plane (the rest shape must lie in
/// a plane z = constant). Warp is x, weft y, diagonal the direction at 45 degrees between them.
struct EffectiveMaterial {
  double e_warp_pa = 0.0;         ///< Young's modulus under uniaxial stress along x (Pa)
  double e_weft_pa = 0.0;         ///< ... along y (Pa)
  double e_diagonal_pa = 0.0;     ///< ... along (1, 1)/sqrt(2) (Pa)
  double nu_warp = 0.0;           ///< Poisson ratio: lateral contraction / stretch, stress along x
  double nu_weft = 0.0;           ///< ... along y
  double nu_diagonal = 0.0;       ///< ... along the diagonal
  double shear_modulus_pa = 0.0;  ///< G: shear stress over engineering shear strain in x, y (Pa)
};

/// Measures the sheet's stiffness tensor C (3x3, Voigt, engineering shear) from three load cases,
/// one per component of a macroscopic strain E: every border particle is moved to E X (X its rest
/// position from the sheet's centre), the others relax to equilibrium under the linearised spring
/// forces (the force Jacobian at rest, solved exactly), and the membrane stress is the virial of
/// the border reactions, (1/A) sum f_b X_b^T, over the thickness. Uniaxial stress along a
/// direction d, (c^2, s^2, cs) in Voigt form, then gives E(d) = 1 / (d^T S d) and
/// nu(d) = -(t^T S d) / (d^T S d), S = C^-1, t the lateral direction. Every spring the complex
/// holds takes part (bending springs carry no in-plane load at rest). Throws std::runtime_error
/// if the network is not rigid (singular reduced system).
EffectiveMaterial measure_effective_material(ClothComplex& lcc, double thickness_m);

/// Young's modulus and Poisson ratio from a literal tensile test along x.
struct StripTension {
  double e_pa = 0.0;  ///< pulling force / (height x thickness) / strain (Pa)
  double nu = 0.0;    ///< minus the mean strain across (top against bottom side) over the strain
};

/// Pulls a rectangular sheet along x at infinitesimal strain: the particles on its left and right
/// sides (the extreme x) are held in x, 0 and the pull, and free to slide in y; one left particle
/// is held in y; its top and bottom sides are free. The interior relaxes exactly as in
/// measure_effective_material(). Free sides let a lattice that is not affine relax near them,
/// which the homogenisation above does not allow: the two agree for a formulation that is exact.
StripTension measure_strip_tension(ClothComplex& lcc, double thickness_m);

}  // namespace tissu
