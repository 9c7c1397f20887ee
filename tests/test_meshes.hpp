#pragma once
/// \file
/// Small closed meshes shared by the tests of several modules. CGAL-free.

#include <Eigen/Core>

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

}  // namespace tissu::test
