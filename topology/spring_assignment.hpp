#pragma once
/// \file
/// The springs of the cloth complex, stored on its edges (structural, bending) and darts (a quad's
/// shear diagonal, couplings): stiffness from the settings or from a material, rest lengths from
/// material coordinates.

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Fills the spring slots of every edge and every dart from `settings` and the material
/// coordinates.
void assign_springs(ClothComplex& lcc, const SpringSettings& settings);

/// Fills the spring slots of the dart's edge (structural, bending) and of the dart itself (shear
/// diagonal, coupling); see assign_springs. The edge's springs come out the same, to the bit,
/// from either of its darts.
void assign_dart_springs(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings);

}  // namespace tissu
