#pragma once
/// \file
/// tissu's own reader of the polygons of a Wavefront OBJ file (`v`, `vt`, `f`), which keeps the
/// file's vertex numbering (assimp's importer renumbers vertices in the order faces use them).

#include <Eigen/Core>
#include <filesystem>
#include <vector>

namespace tissu {

/// The polygons of an OBJ file as written in it, all ids 0-based and in range.
struct ObjPolygons {
  /// #V `v` positions, in file order: file vertex k (0-based) is the (k+1)-th `v` statement
  std::vector<Eigen::Vector3d> positions;
  /// #T `vt` texture coordinates (u, v, w), in file order; v and w are 0 when the file omits them
  std::vector<Eigen::Vector3d> texture_coordinates;
  /// #F polygons of at least 3 ids into positions, in file order
  std::vector<std::vector<int>> faces;
  /// #F lists, the same length as the face's, of ids into texture_coordinates; empty for a face
  /// written without them
  std::vector<std::vector<int>> face_texture_coordinates;
  /// #F line of each `f` statement in the file (1-based), for messages
  std::vector<int> face_lines;
};

/// Reads the `v`, `vt` and `f` statements of the OBJ `file`. Faces give corners as `v`, `v/vt`,
/// `v//vn` or `v/vt/vn`, with 1-based indices, or negative ones counting back from the last
/// element defined before the face (-1 the last); a statement may continue on the next line after
/// a `\`, and `#` starts a comment. Every other statement (points, lines, normals, groups,
/// objects, materials, free-form geometry, writers' own ones) is skipped. Every coordinate must be
/// finite.
///
/// Throws MeshError "<file>: line <n>: <what>" for a line that does not start with a statement
/// keyword (a letter, then letters, digits or underscores), a missing or malformed
/// number, a non-finite coordinate, a face of fewer than 3 corners, an index 0 or out of range,
/// or a face giving texture coordinates at some corners only; "<file>: cannot read mesh: ..."
/// when the file cannot be opened.
ObjPolygons read_obj(const std::filesystem::path& file);

}  // namespace tissu
