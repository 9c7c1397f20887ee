#pragma once
/// \file
/// Which springs a cloth has and how stiff they are. CGAL-free.

#include <optional>

#include "topology/material.hpp"

namespace tissu {

struct SpringKindSettings {
  bool enabled = false;    ///< whether springs of this kind exist
  double stiffness = 0.0;  ///< k of every spring of this kind (N/m), required when enabled
                           ///< and no material is given
  double damping = 0.0;    ///< viscous coefficient nu (N s/m)
};

/// Structural springs lie on every edge, shear springs on both diagonals of every quad, bending
/// springs across every interior edge (see EdgeSprings::bending). With a material, each kind's
/// stiffness comes from it (membrane_stiffness.hpp) and the kinds' own stiffness is unused.
struct SpringSettings {
  SpringKindSettings structural;
  SpringKindSettings shear;
  SpringKindSettings bending;
  std::optional<Material> material;  ///< unset: every spring of a kind has the kind's stiffness
  /// Without a material, whether a refined hinge's bending spring also scales with the hinge's
  /// shape rho = l^2 / A, as rho^3 (spring_assignment.cpp, bending_level_factor), not only with
  /// its area: on for anisotropic remeshing, whose cells may be long along a fold.
  bool bending_follows_hinge_shape = false;
};

}  // namespace tissu
