#pragma once
/// \file
/// Writing a cloth's mesh to an OBJ or PLY file with tissu's own writers, e.g. one file per
/// simulated frame: every vertex in order, in double precision, faces as they are; or to a glTF
/// binary for the web, through assimp's exporter.

#include <Eigen/Core>
#include <filesystem>
#include <string_view>
#include <vector>

#include "topology/indexed_mesh.hpp"
#include "topology/pin_selection.hpp"

namespace tissu {

/// File formats write_mesh can produce.
enum class MeshFormat {
  obj,  ///< Wavefront OBJ, text, without a material library
  ply,  ///< Stanford PLY, binary little-endian
  glb,  ///< glTF 2.0 binary, for the web: float32, y-up, triangles (mesh_encoding.hpp, glb_bytes)
};

/// The format named `name` ("obj" or "ply"). Throws std::invalid_argument naming the accepted
/// values otherwise.
MeshFormat mesh_format_from_string(std::string_view name);

/// The file name extension of `format`, without the dot: "obj", "ply" or "glb".
const char* extension(MeshFormat format);

/// Material (rest) coordinates written beside a mesh's positions, and the cloth frame in which
/// they become texture coordinates.
struct RestCoordinates {
  std::vector<Eigen::Vector3d> rest_m;  ///< #V material coordinates (m), the mesh's vertex order
  ClothFrame frame;                     ///< the cloth's u and v axes (unit), as in the scenario
};

/// Texture coordinates (u, v, w) (m) of material coordinates `rest_m`: their components along an
/// orthonormal frame made from `frame`: u along u_axis, v along v_axis made orthogonal to it, w
/// along the normal u_axis x v_axis. For a flat sheet in the u-v plane (a grid, a planar mesh)
/// (u, v) is an isometric parametrisation of the rest shape, in metres, and w is constant; for a
/// curved rest shape (u, v) is its projection on that plane, and w keeps what it loses, so that
/// rest = u u_axis + v v_axis' + w normal recovers the material coordinates to round-off.
std::vector<Eigen::Vector3d> rest_texture_coordinates(const std::vector<Eigen::Vector3d>& rest_m,
                                                      const ClothFrame& frame);

/// Writes `mesh` to `file`, overwriting it: every vertex, in the mesh's order (unused and
/// coincident ones too), and every face with its 3 or 4 vertex ids as they are. Numbers are
/// written so that they read back to the same doubles: OBJ in text (shortest round-trip
/// decimal), PLY as binary little-endian doubles.
///
/// Texture coordinates, and with `rest` the material coordinates, are written too:
/// - OBJ, when the mesh has UVs (IndexedMesh::face_uvs, the cloth mesh's own, carried through
///   refinement and tearing): one `vt u v` per distinct UV value, in the order the face corners
///   first use them, faces `f a/ta b/tb c/tc` (a seam's two sides have different `vt`); the
///   material coordinates are then not in the file (write PLY for both).
/// - OBJ without UVs, with `rest`: one `vt u v w` per vertex, the rest_texture_coordinates, with
///   the vertex's index (faces `f a/a b/b c/c`), since OBJ has no other per-vertex field;
/// - PLY, with `rest`: vertex properties `s t` (the u and v of rest_texture_coordinates, which
///   most readers take as texture coordinates) and `rest_x rest_y rest_z`, the material
///   coordinates as they are (all double);
/// - PLY, when the mesh has UVs: the face property `texcoord` (a list of doubles, u v for each
///   corner in vertex_indices order: MeshLab's per-wedge texture coordinates).
/// A comment at the top of the file says what each field holds. Without UVs and without `rest`,
/// the file holds positions and faces only.
///
/// The file is written whole or not at all: through a temporary file beside it, renamed over it
/// once complete (lib/atomic_file.hpp), so that a full disk or a killed process never leaves a
/// truncated mesh under its name.
///
/// Throws std::runtime_error naming the file, and writes nothing, if a face refers to a vertex out
/// of range, has fewer than 3 or more than 255 vertices (127 with UVs), the mesh has UVs but not
/// one per corner of every face, `rest` does not have one entry per vertex, or a position or rest
/// position is not finite (inf or NaN); FileWriteError (a std::runtime_error) naming the file and
/// the cause if it cannot be written.
void write_mesh(const std::filesystem::path& file, const IndexedMesh& mesh, MeshFormat format);
void write_mesh(const std::filesystem::path& file, const IndexedMesh& mesh,
                const RestCoordinates& rest, MeshFormat format);

}  // namespace tissu
