#pragma once
/// \file
/// A scene's obstacle meshes turned into the flat vertex array the renderer uploads, with normals
/// that keep curved surfaces smooth and box edges sharp. GL-free, so it can be tested on its own.

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "topology/indexed_mesh.hpp"

namespace tissu {

struct ObstacleGeometry {
  /// #T*3 triangle corners (polygons fanned from their first vertex), cloth_vertex_floats each:
  /// position (m, 3), corner normal (3), strain (1, always 0), the cloth's layout.
  std::vector<float> triangles;
  Eigen::AlignedBox3d bounds;  ///< of every obstacle vertex used by a face; empty if none
};

/// Faces meeting at more than this angle (degrees) keep a crease between them. A tessellated
/// sphere or capsule turns by a few degrees between neighbouring faces, a box by 90.
inline constexpr double obstacle_crease_angle_deg = 30.0;

/// The corner normal of face f at vertex v is the normalised sum of the vector areas of the faces
/// around v whose normal is within obstacle_crease_angle_deg of f's (f included): smooth shading
/// across gentle bends, flat shading on each side of a sharp edge. Throws std::invalid_argument
/// naming the obstacle and element when a face has fewer than 3 vertices or an id out of range,
/// or a position is not finite.
ObstacleGeometry obstacle_geometry(std::span<const IndexedMesh> obstacles);

}  // namespace tissu
