#pragma once
/// \file
/// Small closed meshes shared by the tests of several modules, and a way to join them. CGAL-free.

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "topology/indexed_mesh.hpp"

namespace tissu::test {

/// A closed cube of half side `half` (m) around `centre`: 8 corners, 12 triangles,
/// counter-clockwise seen from outside. Corner i has x, y, z = + for bits 0, 1, 2 of i.
inline IndexedMesh cube_mesh(const Eigen::Vector3d& centre, double half) {
  IndexedMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.push_back(
        centre + half * Eigen::Vector3d((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1));
  mesh.faces = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
  return mesh;
}

/// `mesh` with `part`'s vertices and faces added after its own (a soup of parts).
inline IndexedMesh with_part(IndexedMesh mesh, const IndexedMesh& part) {
  const int offset = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (std::vector<int> face : part.faces) {
    for (int& v : face) v += offset;
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

}  // namespace tissu::test
