#pragma once
/// \file
/// Marks the particles chosen by pin selectors.

#include "topology/cloth_complex.hpp"
#include "topology/pin_selection.hpp"

namespace tissu {

/// Gives every particle chosen by one of `selectors` that selector's pin_group (the last selector
/// choosing it wins), pins it unless the selector takes hold later (attach_at_s > 0) and gives it
/// the selector's handle velocity at t = 0; returns how many are pinned.
/// A side is the set of vertices whose coordinate along the frame axis is within 1e-6 of the
/// cloth's extent from the extreme; a corner is the end of the top or bottom side nearest to the
/// left or right. Throws PinError ("pins[2]: ...") when a selector selects nothing or an index is
/// not a vertex of the input.
int apply_pins(ClothComplex& lcc, const std::vector<PinSelector>& selectors,
               const ClothFrame& frame);

}  // namespace tissu
