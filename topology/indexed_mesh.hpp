#pragma once
/// \file
/// A plain indexed polygon mesh: what mesh files are read into and what the cloth builder takes.
/// CGAL-free, so lib/ and apps/ can use it without the heavy headers.

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

namespace tissu {

struct IndexedMesh {
  std::vector<Eigen::Vector3d> vertices;  ///< #V positions (m)
  std::vector<std::vector<int>> faces;    ///< #F faces, 3 or 4 vertex ids, counter-clockwise
  /// Texture coordinates (u, v) per face corner, as the mesh file gives them (dimensionless):
  /// empty when the mesh has none; otherwise #F lists, face_uvs[f][k] at corner k of faces[f].
  /// Per corner, not per vertex, so that a UV seam (a vertex with different UVs in its faces)
  /// is kept. A list is empty, or the lists fewer than the faces, only in a mesh as a reader
  /// returns it before validate_indexed_mesh, which refuses a mesh with UVs on some faces only.
  std::vector<std::vector<Eigen::Vector2d>> face_uvs;

  bool has_uvs() const { return !face_uvs.empty(); }
};

/// Thrown when a mesh cannot hold a cloth; the message names the element and what was expected.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Checks that `mesh` can become a cloth complex: not empty, finite coordinates, faces of 3 or 4
/// vertex ids in range and distinct, no degenerate (zero-area) face, every edge shared by at most
/// two faces (manifold) and traversed in opposite directions by those two (consistent
/// orientation), every vertex surrounded by a single fan of faces (no "bow-tie" vertex where
/// two fans touch at a point), and texture coordinates at every face or at none (one finite
/// (u, v) per corner). Throws MeshError naming the first offending vertex, face or edge.
void validate_indexed_mesh(const IndexedMesh& mesh);

/// `mesh` with each quad cut into two triangles along its shorter diagonal (the better-shaped
/// pair), keeping the orientation and each corner's texture coordinates; triangles are kept as
/// they are. Adaptive refinement uses this once, before building, since it bisects triangles only.
IndexedMesh triangulate_quads(const IndexedMesh& mesh);

}  // namespace tissu
