#include "topology/grid_mesh.hpp"

#include <Eigen/Geometry>
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
  if (o.pleats < 0 || (o.pleats > 0 && !(o.gathered_width > 0.0 && o.gathered_width < o.width))) {
    throw std::invalid_argument("grid pleats need a gathered width between 0 and the grid width");
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

/// Arc length (m) of s -> (g s, A sin(2 pi n s / W)) over s in [0, W], by the midpoint rule.
double pleat_arc_length(double width_m, double gather, int pleats, double amplitude_m) {
  constexpr int samples = 2000;
  const double k = 2.0 * M_PI * pleats / width_m;
  double length_m = 0.0;
  for (int q = 0; q < samples; ++q) {
    const double s = (q + 0.5) * width_m / samples;
    length_m += std::hypot(gather, amplitude_m * k * std::cos(k * s)) * width_m / samples;
  }
  return length_m;
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

std::vector<Eigen::Vector3d> grid_initial_positions(const GridOptions& o) {
  std::vector<Eigen::Vector3d> positions = make_grid_mesh(o).vertices;
  if (o.pleats == 0) return positions;
  const double gather = o.gathered_width / o.width;
  // the arc length grows with the amplitude: bisect for the one that equals the flat width
  double low_m = 0.0, high_m = o.width;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double mid_m = 0.5 * (low_m + high_m);
    (pleat_arc_length(o.width, gather, o.pleats, mid_m) < o.width ? low_m : high_m) = mid_m;
  }
  const Eigen::Vector3d normal = o.u_axis.cross(o.v_axis);
  const double k = 2.0 * M_PI * o.pleats / o.width;
  for (Eigen::Vector3d& p : positions) {
    const double s = (p - o.origin).dot(o.u_axis);
    p += (gather - 1.0) * s * o.u_axis + low_m * std::sin(k * s) * normal;
  }
  return positions;
}

}  // namespace tissu
