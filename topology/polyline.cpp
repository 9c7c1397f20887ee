#include "topology/polyline.hpp"

#include <algorithm>
#include <limits>

#include "solver/collision/primitive_distance.hpp"

namespace tissu {

PolylineProjection project_on_polyline(const std::vector<Eigen::Vector3d>& points,
                                       const Eigen::Vector3d& p) {
  PolylineProjection best{(p - points.front()).norm(), 0.0};
  double start_m = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Eigen::Vector3d& a = points[k];
    const Eigen::Vector3d& b = points[k + 1];
    const double t = nearest_on_segment(p, a, b);
    const double distance_m = (p - (a + t * (b - a))).norm();
    if (distance_m < best.distance_m) best = {distance_m, start_m + t * (b - a).norm()};
    start_m += (b - a).norm();
  }
  return best;
}

double polyline_segment_distance(const std::vector<Eigen::Vector3d>& points,
                                 const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  double nearest_m = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Eigen::Vector3d& p = points[k];
    const Eigen::Vector3d& q = points[k + 1];
    const Eigen::Vector2d st = nearest_between_segments(p, q, a, b);
    nearest_m = std::min(nearest_m, ((p + st[0] * (q - p)) - (a + st[1] * (b - a))).norm());
  }
  return nearest_m;
}

}  // namespace tissu
