#pragma once
/// \file
/// The "cloth" and "pins" sections of a scenario.

#include "lib/scenario/json_reader.hpp"
#include "lib/scenario/scenario.hpp"

namespace tissu {

/// Reads "cloth" into scenario.cloth, areal_density and springs.
void read_cloth(JsonObjectReader cloth, Scenario& scenario);

/// Reads the "pins" array.
std::vector<PinSelector> read_pins(JsonObjectReader& top);

}  // namespace tissu
