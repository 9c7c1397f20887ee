#pragma once
/// \file
/// What one rendered frame shows: the cloth's current mesh and what is drawn on and around it.
/// CGAL-free: the driver fills it from the cloth complex (or from a saved frame mesh).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "topology/indexed_mesh.hpp"

namespace tissu {

/// One frame's content.
struct RenderScene {
  const IndexedMesh* mesh = nullptr;  ///< the cloth, not owned: #V positions (m), faces of 3 or 4
  std::vector<std::uint8_t> pinned;   ///< #V, non-zero for a pinned particle; empty: none pinned
  /// #F, the strain of each face for ColorMode::strain: (current area or edge length) / rest - 1,
  /// so 0 is at rest and 0.1 is 10 % stretched; empty: all zero.
  std::vector<float> face_strain;
  /// #F, the refinement level of each face for ColorMode::level, log2(A_input / A); empty: all 0.
  std::vector<float> face_level;
  /// #F, for ColorMode::sizing_term, the sizing field's term that held each face at the last
  /// adaptation pass, as a SizingTerm value (0 none to 5 maximum edge length); empty: all 0.
  std::vector<float> face_sizing_term;
  std::optional<double> ground_height_m;  ///< height (z, m) of a horizontal ground plane, if any
  /// Rigid obstacles, not owned: closed triangle (or polygon) meshes, counter-clockwise seen from
  /// outside, positions (m) where they are at this frame's time. Empty: none.
  std::span<const IndexedMesh> obstacles;
};

}  // namespace tissu
