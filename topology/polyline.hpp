#pragma once
/// \file
/// Where a point lies relative to a polyline: for weak lines and knife cuts. CGAL-free.

#include <Eigen/Core>
#include <vector>

namespace tissu {

/// The point of a polyline nearest to a point.
struct PolylineProjection {
  double distance_m = 0.0;    ///< from the point to the polyline (m)
  double arc_length_m = 0.0;  ///< along the polyline from its first vertex to the nearest point (m)
};

/// Projects `p` on the polyline through `points` (at least one point); the first nearest segment
/// wins a tie.
PolylineProjection project_on_polyline(const std::vector<Eigen::Vector3d>& points,
                                       const Eigen::Vector3d& p);

/// Distance between the polyline through `points` (at least two) and the segment [a, b] (m).
double polyline_segment_distance(const std::vector<Eigen::Vector3d>& points,
                                 const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace tissu
