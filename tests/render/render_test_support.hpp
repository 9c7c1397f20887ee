#pragma once
/// \file
/// Meshes and pixel helpers shared by the render tests.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

#include "lib/render/image.hpp"
#include "lib/render/render_scene.hpp"
#include "tests/test_meshes.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu::test {

/// A side x side square in the plane z = 0 centred at `centre`, cut into n x n quads (or 2 n^2
/// triangles), counter-clockwise seen from +z.
inline IndexedMesh square_mesh(double side, int n, bool quads = true,
                               const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
  IndexedMesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.vertices.push_back(centre + Eigen::Vector3d(side * (double(i) / n - 0.5),
                                                       side * (double(j) / n - 0.5), 0.0));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if (quads) {
        mesh.faces.push_back({a, b, c, d});
      } else {
        mesh.faces.push_back({a, b, c});
        mesh.faces.push_back({a, c, d});
      }
    }
  }
  return mesh;
}

/// A scene of `mesh` alone: nothing pinned, no strain, no ground.
inline RenderScene scene_of(const IndexedMesh& mesh) {
  RenderScene scene;
  scene.mesh = &mesh;
  return scene;
}

/// Pixel (x, y) of `image` as floats in [0, 1].
inline Eigen::Vector3f color_at(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return Eigen::Vector3f(p[0], p[1], p[2]) / 255.0f;
}

/// Distance between two colours (RGB in [0, 1]).
inline float color_distance(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  return (a - b).norm();
}

}  // namespace tissu::test
