#pragma once
/// \file
/// Two primitives of the cloth in contact, written the same way whether they are a vertex and a
/// triangle or two edges, so that one response handles both. CGAL-free.

#include <Eigen/Core>
#include <array>

namespace tissu {

/// The relative position of the two closest points is r = sum_k weight[k] x[particle[k]]:
/// vertex-triangle (p; a, b, c): weights (1, -alpha, -beta, -gamma), barycentric on the triangle;
/// edge-edge (p0, p1; q0, q1): weights (1 - s, s, -(1 - t), -t). `normal` is unit and points
/// from the second primitive to the first, on the side where the pair started the step.
struct ContactPair {
  std::array<int, 4> particle{};
  Eigen::Vector4d weight = Eigen::Vector4d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double distance_m = 0.0;  ///< r . normal where the contact was found (m)
};

/// A vertex-triangle candidate (vertex, triangle's three corners) or an edge-edge candidate (the
/// two ends of each edge), from the broad phase.
struct CandidatePair {
  std::array<int, 4> particle{};
  bool edge_edge = false;

  /// How many of `particle` are the first primitive's corners; the rest are the second's.
  int first_primitive_size() const { return edge_edge ? 2 : 1; }
};

}  // namespace tissu
