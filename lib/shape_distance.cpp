#include "lib/shape_distance.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include "solver/collision/primitive_distance.hpp"
#include "topology/mesh_obstacle.hpp"

namespace tissu {
namespace {

constexpr double rest_tie_m = 1e-9;  // rest-space distances this close are the same point's

struct Triangle {
  int a, b, c;
};

std::vector<Triangle> triangles_of(const IndexedMesh& mesh) {
  std::vector<Triangle> out;
  for (const std::vector<int>& f : mesh.faces) {
    for (std::size_t k = 2; k < f.size(); ++k) out.push_back({f[0], f[k - 1], f[k]});
  }
  return out;
}

}  // namespace

std::vector<Eigen::Vector3d> material_point_positions(
    const MaterialSurface& other, const std::vector<Eigen::Vector3d>& rest_points_m,
    const std::vector<Eigen::Vector3d>* near_m) {
  if (other.rest_m.size() != other.current.vertices.size() ||
      (near_m != nullptr && near_m->size() != rest_points_m.size())) {
    throw std::invalid_argument("material_point_positions: one rest position per vertex expected");
  }
  const std::vector<Triangle> triangles = triangles_of(other.current);
  if (triangles.empty())
    throw std::invalid_argument("material_point_positions: no face to locate on");
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const Triangle& t : triangles) {
    Eigen::AlignedBox3d box(other.rest_m[t.a]);
    boxes.push_back(box.extend(other.rest_m[t.b]).extend(other.rest_m[t.c]));
  }

  // the rest-space distance from X to triangle k and the current position of its nearest point
  const auto locate = [&](std::size_t k, const Eigen::Vector3d& X, Eigen::Vector3d& here_m) {
    const Triangle& t = triangles[k];
    const std::vector<Eigen::Vector3d>& X_k = other.rest_m;
    const Eigen::Vector3d l = nearest_on_triangle(X, X_k[t.a], X_k[t.b], X_k[t.c]);
    const std::vector<Eigen::Vector3d>& x = other.current.vertices;
    here_m = l[0] * x[t.a] + l[1] * x[t.b] + l[2] * x[t.c];
    return (l[0] * X_k[t.a] + l[1] * X_k[t.b] + l[2] * X_k[t.c] - X).norm();
  };
  std::vector<Eigen::Vector3d> positions(rest_points_m.size());
  for (std::size_t i = 0; i < rest_points_m.size(); ++i) {
    const Eigen::Vector3d& X = rest_points_m[i];
    // nearest triangle in rest space; a box farther than the best distance cannot hold a nearer one
    double best_m = std::numeric_limits<double>::infinity();
    Eigen::Vector3d here_m;
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      if (boxes[k].exteriorDistance(X) < best_m) best_m = std::min(best_m, locate(k, X, here_m));
    }
    // of the triangles that nearest (both lips of a tear hold the points along it), the one whose
    // point is nearest `near_m` now, or the first
    const double tied_m = best_m + rest_tie_m;
    double gap_m = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      if (boxes[k].exteriorDistance(X) > tied_m || locate(k, X, here_m) > tied_m) continue;
      const double here_gap_m = near_m != nullptr ? (here_m - (*near_m)[i]).norm() : 0.0;
      if (here_gap_m < gap_m) {
        gap_m = here_gap_m;
        positions[i] = here_m;
      }
      if (near_m == nullptr) break;
    }
  }
  return positions;
}

ShapeDistance material_point_distance(const MaterialSurface& other,
                                      const MaterialSurface& reference) {
  if (reference.rest_m.size() != reference.current.vertices.size()) {
    throw std::invalid_argument("material_point_distance: one rest position per vertex expected");
  }
  const std::vector<Eigen::Vector3d> positions =
      material_point_positions(other, reference.rest_m, &reference.current.vertices);
  ShapeDistance out;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double gap_m = (positions[i] - reference.current.vertices[i]).norm();
    out.mean_m += gap_m;
    out.max_m = std::max(out.max_m, gap_m);
    ++out.points;
  }
  if (out.points > 0) out.mean_m /= out.points;
  return out;
}

ShapeDistance surface_distance_between(const IndexedMesh& a, const IndexedMesh& b) {
  ShapeDistance out;  // mean_m: the mean of the two directions' means
  for (const auto& [from, to] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    // an open mesh's distance field is unsigned; a closed one's is signed, hence the magnitude
    const std::shared_ptr<const SurfaceQuery> surface = make_mesh_surface(*to);
    double sum_m = 0.0;
    for (const Eigen::Vector3d& x : from->vertices) {
      const double gap_m = std::abs(surface->distance(x).distance_m);
      sum_m += gap_m;
      out.max_m = std::max(out.max_m, gap_m);
    }
    if (!from->vertices.empty())
      out.mean_m += 0.5 * sum_m / static_cast<double>(from->vertices.size());
    out.points += static_cast<int>(from->vertices.size());
  }
  return out;
}

}  // namespace tissu
