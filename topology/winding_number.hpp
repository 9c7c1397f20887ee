#pragma once
/// \file
/// The generalised winding number of a triangle soup (Jacobson, Kavan & Sorkine-Hornung 2013),
/// evaluated hierarchically (Barill, Dickson, Schmidt, Levin & Jacobson 2018). CGAL-free.
///
/// w(x) = 1/(4 pi) sum_t Omega_t(x), Omega_t the signed solid angle triangle t subtends at x. For
/// a closed, outward-facing surface w is 1 inside and 0 outside; where closed parts overlap it
/// counts them (2 inside two parts), and it stays defined on soups: duplicate-free faces, several
/// parts, touching or non-manifold edges. "Inside" is w > 1/2. A closed obstacle mesh counts a
/// ray's crossings instead, which is cheaper (mesh_obstacle.hpp); this tree is where that count
/// falls back to when every ray it tries runs through an edge or a vertex.

#include <Eigen/Core>
#include <vector>

namespace tissu {

/// Omega (sr) of triangle (a, b, c) seen from x, positive when x is on the side its normal
/// (b - a) x (c - a) points away from. Van Oosterom & Strackee 1983:
/// tan(Omega / 2) = a.(b x c) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|), corners relative to
/// x.
double solid_angle_sr(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& x);

/// A bounding-volume tree over triangles. A node far from x (farther than `far_ratio` times its
/// radius) is replaced by its dipole: Omega ~ A.(p - x) / |p - x|^3, A the sum of its triangles'
/// area vectors, p their area-weighted centroid (Barill et al. 2018, first order). The error is
/// about (r / d)^2 of the node's solid angle; far_ratio 2 keeps it far below the 1/2 that the
/// inside test can tolerate (tests/topology/winding_number_test.cpp measures it).
class WindingNumberTree {
 public:
  /// Three corners per triangle (m), counter-clockwise seen from outside.
  explicit WindingNumberTree(std::vector<Eigen::Vector3d> corners, double far_ratio = 2.0);

  /// w(x), hierarchically.
  double winding_number(const Eigen::Vector3d& x) const;
  /// w(x) summed over every triangle, for reference.
  double exact_winding_number(const Eigen::Vector3d& x) const;

 private:
  struct Node {
    Eigen::Vector3d centre_m;   ///< area-weighted centroid of its triangles
    Eigen::Vector3d area_m2;    ///< sum of 1/2 (b - a) x (c - a)
    double radius_m = 0.0;      ///< every corner of its triangles lies within it of centre_m
    int first = 0, count = 0;   ///< its triangles: m_order[first, first + count)
    int left = -1, right = -1;  ///< children, -1 for a leaf
  };

  int build(int first, int count);
  double triangle_solid_angle_sr(int triangle, const Eigen::Vector3d& x) const;

  std::vector<Eigen::Vector3d> m_corners;
  std::vector<int> m_order;   ///< triangle ids, grouped by node
  std::vector<Node> m_nodes;  ///< m_nodes[0] is the root
  double m_far_ratio;
};

}  // namespace tissu
