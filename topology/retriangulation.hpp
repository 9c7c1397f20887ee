#pragma once
/// \file
/// Whether new triangles over a patch of cloth keep its rest region: the condition under which a
/// flip or a collapse leaves the rest area, and so every mass, unchanged.

#include <Eigen/Geometry>
#include <vector>

namespace tissu {

/// A triangle of material coordinates, by its corners (m).
struct RestTriangle {
  Eigen::Vector3d a, b, c;
  /// 1/2 (b - a) x (c - a) (m^2): the area times the unit normal of the corners' order.
  Eigen::Vector3d vector_area_m2() const { return 0.5 * (b - a).cross(c - a); }
};

/// Whether `after` tiles the rest region `before` tiles (both non-empty): every new triangle faces
/// the way the old ones face together, with at least 1e-9 of their area along that normal (none
/// degenerate or turned over), and the new areas add up to the old ones' to `relative_tolerance`.
/// Triangles over a planar region pass exactly when they cover it without overlap; a region whose
/// material coordinates are curved (a garment's) passes only where it is flat.
bool keeps_rest_region(const std::vector<RestTriangle>& before,
                       const std::vector<RestTriangle>& after, double relative_tolerance = 1e-12);

/// The smallest of the triangles' qualities 4 sqrt(3) A / (l1^2 + l2^2 + l3^2): 1 for an
/// equilateral triangle, 0 for a degenerate one (about 0.87 for a grid's right isosceles halves).
double lowest_quality(const std::vector<RestTriangle>& triangles);

}  // namespace tissu
