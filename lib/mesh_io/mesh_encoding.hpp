#pragma once
/// \file
/// The contents of the files write_mesh writes (write_mesh.hpp says what they hold). Internal to
/// lib/mesh_io: the callers have checked the face ids and sizes.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "topology/indexed_mesh.hpp"

namespace tissu {

/// Per-vertex rest data written beside the positions, both in the mesh's vertex order.
struct VertexRestData {
  const std::vector<Eigen::Vector3d>& texture_uvw;  ///< #V rest_texture_coordinates (m)
  const std::vector<Eigen::Vector3d>& rest_m;       ///< #V material coordinates (m)
};

/// The text of an OBJ file of `mesh`: `vt` are the mesh's UVs when it has some (one per distinct
/// value), else one per vertex, its rest texture coordinates, when `rest` is given.
std::string obj_text(const IndexedMesh& mesh, const VertexRestData* rest);

/// The bytes of a binary little-endian PLY file of `mesh`, with the vertex properties
/// s t rest_x rest_y rest_z when `rest` is given, and the face property texcoord when the mesh
/// has UVs.
std::string ply_bytes(const IndexedMesh& mesh, const VertexRestData* rest);

/// The bytes of a glTF 2.0 binary (.glb) of `mesh`, for web viewers: positions (float32, m) and
/// area-weighted vertex normals turned from tissu's z-up to glTF's y-up ((x, y, z) -> (x, z, -y)),
/// triangles (a quad split along its first diagonal), TEXCOORD_0 the (u, v) of `texture_uvw` when
/// given, one double-sided material; vertex k is vertex k of the mesh. Throws std::runtime_error
/// with assimp's message if its exporter fails.
std::string glb_bytes(const IndexedMesh& mesh, const std::vector<Eigen::Vector3d>* texture_uvw);

}  // namespace tissu
