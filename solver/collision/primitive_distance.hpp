#pragma once
/// \file
/// Closest points between a point and a triangle, and between two segments. CGAL-free.

#include <Eigen/Core>

namespace tissu {

/// Parameter t in [0, 1] of the point from + t (to - from) of a segment nearest to p; 0 for a
/// segment of zero length.
double nearest_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& from,
                          const Eigen::Vector3d& to);

/// Barycentric coordinates (of a, b, c) of the point of triangle abc nearest to p: the projection
/// on its plane when it falls inside, else the nearest point of its nearest edge (Ericson,
/// Real-Time Collision Detection, 2005, section 5.1.5). A degenerate triangle gives its nearest
/// edge point.
Eigen::Vector3d nearest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Parameters (s, t) in [0, 1]^2 of the closest points p0 + s (p1 - p0) and q0 + t (q1 - q0) of
/// two segments (Ericson 2005, section 5.1.9, with parallel segments handled).
Eigen::Vector2d nearest_between_segments(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                         const Eigen::Vector3d& q0, const Eigen::Vector3d& q1);

}  // namespace tissu
