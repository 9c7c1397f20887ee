#pragma once
/// \file
/// The input mesh's texture coordinates, carried per face corner on the darts
/// (CornerMechanics::uv) through splits, merges and tears.

#include <Eigen/Core>

#include "topology/cloth_complex.hpp"

namespace tissu {

/// Whether the cloth carries its mesh's texture coordinates: build_cloth_complex gives every dart
/// one when the mesh has UVs (IndexedMesh::face_uvs) and none otherwise, and every edit keeps it
/// so (validity_problems checks it). False for an empty complex.
bool has_corner_uvs(const ClothComplex& lcc);

/// The UV of the dart's origin in the dart's face.
Eigen::Vector2d corner_uv(const ClothComplex& lcc, Dart_const_handle dart);

/// Whether the edge of `dart` is a UV seam: its two faces give one of its ends different UVs.
/// False on the border and on a cloth without UVs.
bool is_uv_seam(const ClothComplex& lcc, Dart_const_handle dart);

/// Gives each dart leaving `vertex`, just inserted into an edge (a, b) by insert_cell_0_in_cell_1
/// so that its faces run a -> vertex -> b, the midpoint of the UVs of a and b in that face:
/// uv(d) = (uv(previous(d)) + uv(next(d))) / 2, linear interpolation at the edge's midpoint, as for
/// the vertex's position and material coordinates. Each face interpolates its own corners' UVs,
/// so a split along a UV seam keeps the seam. On a cloth without UVs, the new darts get none.
void interpolate_uvs_at_inserted_vertex(ClothComplex& lcc, Vertex_handle vertex);

/// Gives both darts of an edge just inserted across a face by insert_cell_1_in_cell_2 the UVs of
/// their origins in the face it cut: uv(d) = uv(next(opposite<2>(d))), the dart that leaves the
/// same corner in the other half of that face. On a cloth without UVs, the new darts get none.
void copy_uvs_to_inserted_edge(ClothComplex& lcc, Dart_handle new_edge);

}  // namespace tissu
