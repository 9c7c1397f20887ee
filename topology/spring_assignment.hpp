#pragma once
/// \file
/// The springs of the cloth complex, stored on its darts: stiffness from the settings or from a
/// material, rest lengths from material coordinates.

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Fills the three spring slots of every dart from `settings` and the material coordinates.
void assign_springs(ClothComplex& lcc, const SpringSettings& settings);

/// Fills the three spring slots of one dart (see assign_springs).
void assign_dart_springs(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings);

}  // namespace tissu
