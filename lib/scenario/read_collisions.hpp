#pragma once
/// \file
/// The "obstacles" and "self_collision" sections of a scenario.

#include <string>
#include <vector>

#include "lib/scenario/json_reader.hpp"
#include "solver/collision/obstacle.hpp"
#include "solver/collision/self_collision.hpp"

namespace tissu {

/// Reads the "obstacles" array of the top-level object, if any: one object per obstacle, its
/// "type" choosing the keys it takes (docs/scenario.md). Remarks on mesh files (faces dropped)
/// are appended to `notes`, one line each.
std::vector<Obstacle> read_obstacles(JsonObjectReader& top, std::vector<std::string>& notes);

/// Reads "self_collision"; enabled unless it says "enabled": false.
SelfCollisionOptions read_self_collision(JsonObjectReader self_collision);

}  // namespace tissu
