#include "topology/grid_mesh.hpp"

#include <cmath>
#include <stdexcept>

namespace tissu {
namespace {

void check_grid_options(const GridOptions& o) {
  if (!(o.width > 0.0) || !(o.height > 0.0) || !std::isfinite(o.width) ||
      !std::isfinite(o.height)) {
    throw std::invalid_argument("grid width and height must be positive and finite");
  }
  if (o.cells_u < 1 || o.cells_v < 1) {
    throw std::invalid_argument("grid must have at least one cell along u and along v");
  }
  constexpr double tolerance = 1e-9;
  if (std::abs(o.u_axis.norm() - 1.0) > tolerance || std::abs(o.v_axis.norm() - 1.0) > tolerance ||
      std::abs(o.u_axis.dot(o.v_axis)) > tolerance) {
    throw std::invalid_argument("grid axes u and v must be orthonormal");
  }
}

bool uses_forward_diagonal(DiagonalPattern pattern, int i, int j) {
  switch (pattern) {
    case DiagonalPattern::forward:
      return true;
    case DiagonalPattern::backward:
      return false;
    case DiagonalPattern::alternating:
      return (i + j) % 2 == 0;
  }
  return true;
}

}  // namespace

IndexedMesh make_grid_mesh(const GridOptions& o) {
  check_grid_options(o);
  IndexedMesh mesh;
  const int nu = o.cells_u + 1;
  const double du = o.width / o.cells_u;
  const double dv = o.height / o.cells_v;
  mesh.vertices.reserve(static_cast<std::size_t>(nu) * (o.cells_v + 1));
  for (int j = 0; j <= o.cells_v; ++j) {
    for (int i = 0; i < nu; ++i) {
      mesh.vertices.push_back(o.origin + (i * du) * o.u_axis + (j * dv) * o.v_axis);
    }
  }
  auto id = [nu](int i, int j) { return j * nu + i; };
  for (int j = 0; j < o.cells_v; ++j) {
    for (int i = 0; i < o.cells_u; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (o.cells == GridCells::quads) {
        mesh.faces.push_back({a, b, c, d});
      } else if (uses_forward_diagonal(o.diagonal, i, j)) {
        mesh.faces.push_back({a, b, c});
        mesh.faces.push_back({a, c, d});
      } else {
        mesh.faces.push_back({a, b, d});
        mesh.faces.push_back({b, c, d});
      }
    }
  }
  return mesh;
}

}  // namespace tissu
