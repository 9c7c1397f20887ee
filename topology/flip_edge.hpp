#pragma once
/// \file
/// Flips the edge shared by two triangles of the cloth: the step of anisotropic remeshing that
/// turns cells to follow the sizing metric (Narain, Samii & O'Brien 2012, section 5.2).

#include <optional>
#include <string>

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Why the edge of `dart`, (a, b) between the triangles (a, b, c) and (b, a, e), cannot be
/// flipped to (c, e) without changing the cloth, or nothing when it can:
/// - it is on the border, or a face beside it is not a triangle;
/// - c and e are already joined by an edge;
/// - the two faces' texture coordinates differ at a or b (a UV seam, corner_uvs.hpp);
/// - in material coordinates, the quad (a, e, b, c) is not planar and convex: the triangles
///   (c, a, e) and (e, b, c) must face the way the old pair faces and cover the same area, to
///   1e-12 relative, so that the rest area, and with it every mass, is unchanged.
std::optional<std::string> flip_refusal(const ClothComplex& lcc, Dart_const_handle dart);

/// Replaces the edge (a, b) of `dart` by (c, e) (flip_refusal() must give nothing: throws
/// std::invalid_argument otherwise). The particles do not move; the two new faces take the
/// mean of the old ones' input areas (FaceRest::input_area, the bending springs' reference,
/// whose sum is kept) and of their sizing; rest areas, masses and springs are recomputed around
/// them (local_update.hpp), and the new edge's corners take the UVs of their faces. Returns the
/// dart c -> e. The corners' masses change (each triangle lumps a third of its mass on each
/// corner): the free ones among them take one common velocity change that keeps their linear
/// momentum.
Dart_handle flip_edge(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings);

}  // namespace tissu
