#pragma once
/// \file
/// Rigid motions and rotations in a scenario: an obstacle's or a pin handle's "motion" object.

#include <Eigen/Core>
#include <optional>

#include "lib/scenario/json_reader.hpp"
#include "solver/rigid_motion.hpp"

namespace tissu {

/// A rotation object: about "axis" (default +z) by exactly one of "angle" (rad) or "degrees"; as
/// a rotation vector (unit axis times angle, rad).
Eigen::Vector3d read_rotation_vector(JsonObjectReader rotation);

/// A "motion" object (docs/scenario.md): "velocity" (a constant drift, m/s), "keyframes" (each
/// {"time": s, "offset": [x, y, z] m, "rotation": {...}}, times increasing), "interpolation"
/// ("linear" or "smooth") and "pivot" (m), the point rotations turn about. Without "pivot",
/// `default_pivot` is used, or, when it is nullopt, a keyframe that rotates is an error.
RigidMotion read_motion(JsonObjectReader motion, std::optional<Eigen::Vector3d> default_pivot);

}  // namespace tissu
