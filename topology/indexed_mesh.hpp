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
/// two fans touch at a point). Throws MeshError naming the first offending vertex, face or edge.
void validate_indexed_mesh(const IndexedMesh& mesh);

/// `mesh` with each quad cut into two triangles along its shorter diagonal (the better-shaped
/// pair), keeping the orientation; triangles are kept as they are. Adaptive refinement uses this
/// once, before building, since it bisects triangles only.
IndexedMesh triangulate_quads(const IndexedMesh& mesh);

}  // namespace tissu
