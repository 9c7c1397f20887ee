#pragma once
/// \file
/// A "mesh" obstacle of a scenario: its file, placed, and optionally animated by a point cache or
/// by keyframe meshes.

#include <string>
#include <vector>

#include "lib/scenario/json_reader.hpp"
#include "solver/collision/obstacle.hpp"

namespace tissu {

/// A mesh obstacle's parts (separate_parts: a torso, an arm), each its own surface, fixed or
/// animated; the contacts resolve them one after the other.
struct MeshObstacleParts {
  std::vector<std::shared_ptr<const SurfaceQuery>> surfaces;        ///< at t = 0
  std::vector<std::shared_ptr<const SurfaceAnimation>> animations;  ///< one per part, or none
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  ///< the mean of all its triangle corners
};

/// Reads the keys of a "mesh" obstacle `o` (file, scale, rotation, position, animation; see
/// docs/scenario.md). Faces the surface dropped are noted in `notes`. Throws ScenarioError naming
/// the key and, for a file's fault, the file and its element.
MeshObstacleParts read_mesh_obstacle(JsonObjectReader& o, std::vector<std::string>& notes);

}  // namespace tissu
