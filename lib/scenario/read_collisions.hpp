#pragma once
/// \file
/// The "obstacles" and "self_collision" sections of a scenario.

#include <vector>

#include "lib/scenario/json_reader.hpp"
#include "solver/collision/obstacle.hpp"
#include "solver/collision/self_collision.hpp"

namespace tissu {

/// Reads the "obstacles" array of the top-level object, if any: one object per obstacle, its
/// "type" choosing the keys it takes (docs/scenario.md).
std::vector<Obstacle> read_obstacles(JsonObjectReader& top);

/// Reads "self_collision"; enabled unless it says "enabled": false.
SelfCollisionOptions read_self_collision(JsonObjectReader self_collision);

}  // namespace tissu
