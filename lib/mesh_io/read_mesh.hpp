#pragma once
/// \file
/// Reading a cloth mesh from a file: OBJ with tissu's own reader (read_obj.hpp), PLY, glTF/GLB,
/// STL and OFF through assimp.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/mesh_io/sandboxed_call.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// A mesh as read_mesh makes it, and how the file's own vertices map to its vertices.
struct NumberedMesh {
  IndexedMesh mesh;
  /// For each vertex of the file, in the file's order (0-based): the mesh vertex it became, or -1
  /// if no face uses it. Empty when the file has no vertex numbering (see no_numbering_reason).
  std::vector<int> mesh_vertex_of_file_vertex;
  /// Why the file's vertices have no numbers, e.g. for STL, whose triangles each store their own
  /// corners; empty when mesh_vertex_of_file_vertex is set.
  std::string no_numbering_reason;

  bool has_vertex_numbering() const { return no_numbering_reason.empty(); }
};

/// Bounds on reading one mesh file, which is untrusted input (docs/scenario.md, "Limits").
struct MeshImportLimits {
  /// larger files are refused before anything reads them (bytes)
  std::uintmax_t max_file_bytes = std::uintmax_t{1} << 30;
  /// time and memory of the child process in which assimp reads the file; by default 20 s plus
  /// 0.1 s per MiB of file, and 2 GiB plus 32 bytes per byte of file, at most three quarters of
  /// the machine's memory
  std::optional<SandboxLimits> importer;
};

/// Reads the polygon mesh in `file` and checks it with validate_indexed_mesh.
///
/// All meshes of the file's scene are merged into one, with their node transforms applied.
/// Positions and texture coordinates are kept (normals, colours and materials are not): vertices
/// at exactly the same position are joined, so a cloth is not cut at UV or normal seams, nor
/// between the groups or objects of one file, and the texture coordinates are kept per face
/// corner (IndexedMesh::face_uvs), so a UV seam survives the joining. Points and lines are
/// ignored, and so are vertices no face uses; triangles and quads are kept as they are (never
/// triangulated). The mesh's vertices come in the order of the file's vertices that faces use.
///
/// Texture coordinates: OBJ's `vt` (u and v; a w is dropped) at the corners of `f v/vt` faces;
/// through assimp, the first UV channel (glTF's TEXCOORD_0, PLY's per-vertex `s t`, `u v` or
/// `texture_u texture_v`), per vertex, so a seam is made of vertices the file duplicates at it.
/// assimp 5.2 reads PLY's per-face `texcoord` lists (MeshLab's, and what write_mesh writes) into
/// its per-vertex UVs, one face's value winning at a seam: read tissu's OBJ output, not its PLY,
/// to get the seams back. A mesh with texture coordinates on some faces only is refused (the
/// message names a face with and one without): give every face UVs, or none.
///
/// The file's vertex numbering (NumberedMesh::mesh_vertex_of_file_vertex) is the order of the `v`
/// statements in OBJ, of the vertex element in PLY, of the vertex list in OFF, and of the POSITION
/// accessor of a glTF/GLB file with a single mesh primitive placed once. STL files, files with
/// several meshes (or one placed several times) and other formats have none.
///
/// The file is untrusted: check_mesh_file (mesh_file_checks.hpp) refuses what is not a regular
/// file, files over `limits.max_file_bytes` and headers whose counts cannot fit in the file;
/// formats other than OBJ are then read by assimp in a child process (sandboxed_call.hpp) within
/// `limits.importer`, so that a crash, endless loop or allocation storm of the importer becomes
/// a MeshError. tissu's own OBJ reader runs in the calling process.
///
/// Throws MeshError whose message starts with the file path: when the file is missing,
/// unreadable or refused by those checks, when the reader fails, crashes or exceeds a limit, or
/// reports indices out of range (for OBJ, naming the line), or when the mesh fails
/// validate_indexed_mesh.
NumberedMesh read_numbered_mesh(const std::filesystem::path& file,
                                const MeshImportLimits& limits = {});

/// The mesh of read_numbered_mesh(file, limits).
IndexedMesh read_mesh(const std::filesystem::path& file, const MeshImportLimits& limits = {});

/// Reads `file` as read_mesh does, but without validate_indexed_mesh and without texture
/// coordinates: for obstacles, which may be triangle soups (non-manifold, several parts, polygons
/// of any size). Throws MeshError starting
/// with the file path when the file cannot be read or the importer fails.
IndexedMesh read_polygons(const std::filesystem::path& file, const MeshImportLimits& limits = {});

/// read_polygons, with the file's vertex numbering (for an animated obstacle, whose point cache
/// or keyframe files give positions per file vertex).
NumberedMesh read_numbered_polygons(const std::filesystem::path& file,
                                    const MeshImportLimits& limits = {});

}  // namespace tissu
