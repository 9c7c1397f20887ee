#pragma once
/// \file
/// A "mesh" obstacle of a scenario: its file, placed, and optionally animated by a point cache or
/// by keyframe meshes.

#include <string>
#include <vector>

#include "lib/scenario/json_reader.hpp"
#include "solver/collision/obstacle.hpp"

namespace tissu {

/// Reads the keys of a "mesh" obstacle `o` (file, scale, rotation, position, animation; see
/// docs/scenario.md) into `obstacle`'s surface and, animated, its animation. Faces the surface
/// dropped are noted in `notes`. Throws ScenarioError naming the key and, for a file's fault, the
/// file and its element.
void read_mesh_obstacle(JsonObjectReader& o, Obstacle& obstacle, std::vector<std::string>& notes);

}  // namespace tissu
