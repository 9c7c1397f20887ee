#pragma once
/// \file
/// A RenderScene turned into the flat vertex arrays the renderer uploads. GL-free, so it can be
/// tested on its own.

#include <Eigen/Geometry>
#include <vector>

#include "lib/render/render_options.hpp"
#include "lib/render/render_scene.hpp"

namespace tissu {

struct ClothGeometry {
  /// #T*3 triangle corners (polygons fanned from their first vertex), 7 floats each: position
  /// (m, 3), smooth vertex normal (3), strain of the face (1).
  std::vector<float> triangles;
  std::vector<float> edges;    ///< #E*2 line ends, 3 floats (m) each: every polygon edge once
  std::vector<float> pins;     ///< #P points, 3 floats (m) each: the pinned vertices
  Eigen::AlignedBox3d bounds;  ///< of face and pinned vertices; empty if none
};

/// Floats per triangle corner in ClothGeometry::triangles.
inline constexpr int cloth_vertex_floats = 7;

/// The geometry of `scene`; its per-face value is the face's level for ColorMode::level, else its
/// strain. Throws std::invalid_argument when the mesh is missing, a face has fewer than 3
/// vertices or an id out of range, a position is not finite, or `pinned`, `face_strain` or
/// `face_level` is neither empty nor of the mesh's vertex or face count.
ClothGeometry cloth_geometry(const RenderScene& scene, ColorMode mode = ColorMode::shaded);

}  // namespace tissu
