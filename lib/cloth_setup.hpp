#pragma once
/// \file
/// The cloth complex a scenario describes. Includes CGAL: for lib/ sources only.

#include "lib/scenario/scenario.hpp"
#include "topology/cloth_complex.hpp"

namespace tissu {

/// Builds the grid or reads the mesh of `scenario`, assigns rest data, masses and springs, and
/// applies the pins. Throws MeshError or PinError (messages name the file or the pins entry).
void build_scenario_cloth(const Scenario& scenario, ClothComplex& lcc);

}  // namespace tissu
