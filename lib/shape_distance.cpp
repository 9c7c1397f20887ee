#include "lib/shape_distance.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tissu {
namespace {

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

/// Barycentric coordinates of the point of triangle (a, b, c) nearest to p (Ericson, Real-Time
/// Collision Detection, 5.1.5: the projection onto the plane, clamped to the triangle by taking the
/// nearest point on an edge when it falls outside).
Eigen::Vector3d nearest_barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac);
  const double d20 = ap.dot(ab), d21 = ap.dot(ac);
  const double det = d00 * d11 - d01 * d01;
  const double v = (d11 * d20 - d01 * d21) / det;
  const double w = (d00 * d21 - d01 * d20) / det;
  if (v >= 0.0 && w >= 0.0 && v + w <= 1.0) return {1.0 - v - w, v, w};
  // outside: the nearest point lies on one of the three edges
  auto on_segment = [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    const Eigen::Vector3d d = to - from;
    return std::clamp((p - from).dot(d) / d.dot(d), 0.0, 1.0);
  };
  const double t_ab = on_segment(a, b), t_bc = on_segment(b, c), t_ca = on_segment(c, a);
  const Eigen::Vector3d candidates[3] = {
      {1.0 - t_ab, t_ab, 0.0}, {0.0, 1.0 - t_bc, t_bc}, {t_ca, 0.0, 1.0 - t_ca}};
  const Eigen::Vector3d* best = &candidates[0];
  double best_m2 = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& l : candidates) {
    const double m2 = (l[0] * a + l[1] * b + l[2] * c - p).squaredNorm();
    if (m2 < best_m2) best_m2 = m2, best = &l;
  }
  return *best;
}

}  // namespace

ShapeDistance material_point_distance(const MaterialSurface& other,
                                      const MaterialSurface& reference) {
  if (other.rest_m.size() != other.current.vertices.size() ||
      reference.rest_m.size() != reference.current.vertices.size()) {
    throw std::invalid_argument("material_point_distance: one rest position per vertex expected");
  }
  const std::vector<Triangle> triangles = triangles_of(other.current);
  if (triangles.empty()) throw std::invalid_argument("material_point_distance: no face to compare");
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const Triangle& t : triangles) {
    Eigen::AlignedBox3d box(other.rest_m[t.a]);
    boxes.push_back(box.extend(other.rest_m[t.b]).extend(other.rest_m[t.c]));
  }

  ShapeDistance out;
  for (std::size_t i = 0; i < reference.rest_m.size(); ++i) {
    const Eigen::Vector3d& X = reference.rest_m[i];
    // nearest triangle in rest space; a box farther than the best distance cannot hold a nearer one
    double best_m = std::numeric_limits<double>::infinity();
    Eigen::Vector3d here_m = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      if (boxes[k].exteriorDistance(X) >= best_m) continue;
      const Triangle& t = triangles[k];
      const Eigen::Vector3d l =
          nearest_barycentric(X, other.rest_m[t.a], other.rest_m[t.b], other.rest_m[t.c]);
      const double rest_gap_m =
          (l[0] * other.rest_m[t.a] + l[1] * other.rest_m[t.b] + l[2] * other.rest_m[t.c] - X)
              .norm();
      if (rest_gap_m < best_m) {
        best_m = rest_gap_m;
        const std::vector<Eigen::Vector3d>& x = other.current.vertices;
        here_m = l[0] * x[t.a] + l[1] * x[t.b] + l[2] * x[t.c];
      }
    }
    const double gap_m = (here_m - reference.current.vertices[i]).norm();
    out.mean_m += gap_m;
    out.max_m = std::max(out.max_m, gap_m);
    ++out.points;
  }
  if (out.points > 0) out.mean_m /= out.points;
  return out;
}

}  // namespace tissu
