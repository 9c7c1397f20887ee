#include "topology/retriangulation.hpp"

#include <algorithm>
#include <cmath>

namespace tissu {

bool keeps_rest_region(const std::vector<RestTriangle>& before,
                       const std::vector<RestTriangle>& after, double relative_tolerance) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double area_before_m2 = 0.0;
  for (const RestTriangle& t : before) {
    normal += t.vector_area_m2();
    area_before_m2 += t.vector_area_m2().norm();
  }
  if (!(normal.norm() > 0.0)) return false;
  normal.normalize();
  double area_after_m2 = 0.0;
  for (const RestTriangle& t : after) {
    const Eigen::Vector3d area = t.vector_area_m2();
    if (!(area.dot(normal) > 1e-9 * area_before_m2)) return false;
    area_after_m2 += area.norm();
  }
  return std::abs(area_after_m2 - area_before_m2) <= relative_tolerance * area_before_m2;
}

double lowest_quality(const std::vector<RestTriangle>& triangles) {
  double lowest = 1.0;
  for (const RestTriangle& t : triangles) {
    const double squares_m2 =
        (t.b - t.a).squaredNorm() + (t.c - t.b).squaredNorm() + (t.a - t.c).squaredNorm();
    const double quality = 4.0 * std::sqrt(3.0) * t.vector_area_m2().norm() / squares_m2;
    lowest = std::min(lowest, squares_m2 > 0.0 ? quality : 0.0);
  }
  return lowest;
}

}  // namespace tissu
