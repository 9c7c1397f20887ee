#pragma once
/// \file
/// Points and vectors between the cloth complex's CGAL kernel (Point3, Vector3) and Eigen, whose
/// 3-vectors the solver, the options and the meshes use. Coordinates are copied as they are.

#include <Eigen/Core>

#include "topology/kernel.hpp"

namespace tissu {

/// The coordinates of `p` as an Eigen vector.
inline Eigen::Vector3d to_eigen(const Point3& p) {
  return {p.x(), p.y(), p.z()};
}

/// The coordinates of `v` as an Eigen vector.
inline Eigen::Vector3d to_eigen(const Vector3& v) {
  return {v.x(), v.y(), v.z()};
}

/// The point of coordinates `x`.
inline Point3 to_point(const Eigen::Vector3d& x) {
  return {x.x(), x.y(), x.z()};
}

/// The vector of coordinates `x`.
inline Vector3 to_vector(const Eigen::Vector3d& x) {
  return {x.x(), x.y(), x.z()};
}

}  // namespace tissu
