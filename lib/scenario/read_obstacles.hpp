#pragma once
/// \file
/// The "obstacles" section of a scenario.

#include <vector>

#include "lib/scenario/json_reader.hpp"
#include "solver/collision/obstacle.hpp"

namespace tissu {

/// Reads the "obstacles" array of the top-level object, if any: one object per obstacle, its
/// "type" choosing the keys it takes (docs/scenario.md).
std::vector<Obstacle> read_obstacles(JsonObjectReader& top);

}  // namespace tissu
