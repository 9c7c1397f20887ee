#pragma once
/// \file
/// Which springs a cloth has and how stiff they are. CGAL-free.

namespace tissu {

struct SpringKindSettings {
  bool enabled = false;    ///< whether springs of this kind exist
  double stiffness = 0.0;  ///< k of every spring of this kind (N/m), required when enabled
  double damping = 0.0;    ///< viscous coefficient nu (N s/m)
};

/// Structural springs lie on every edge, shear springs on both diagonals of every quad, bending
/// springs across every interior edge (see DartMechanics::bending).
struct SpringSettings {
  SpringKindSettings structural;
  SpringKindSettings shear;
  SpringKindSettings bending;
};

}  // namespace tissu
