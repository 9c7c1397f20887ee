#pragma once
/// \file
/// A bounding-volume hierarchy over triangles whose corners move while the triangles stay (an
/// animated body): which triangles share a node is decided once, from one pose; every later pose
/// only refits the nodes' boxes, bottom-up, in time linear in the triangles (van den Bergen 1997,
/// "Efficient collision detection of complex deformable models using AABB trees"). A refitted
/// box holds its triangles as tightly as at the pose the hierarchy was built from; a body whose
/// parts swing far from it gets looser boxes higher up, never wrong answers.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

namespace tissu {

/// The hierarchy's shape: nodes in depth-first order (a node's first child follows it), each
/// leaf a run of at most four triangles in the shape's own triangle order.
class TriangleBvhShape {
 public:
  /// Built from `corners_m`, three per triangle (triangle t's at 3t, 3t + 1, 3t + 2), by median
  /// splits of the triangles' centroids along their box's longest axis.
  explicit TriangleBvhShape(const std::vector<Eigen::Vector3d>& corners_m);

  struct Node {
    /// an inner node's second child (its first is the next node); -1 for a leaf
    int second_child = -1;
    int first = 0;  ///< a leaf's first position in triangle_order()
    int count = 0;  ///< a leaf's triangle count; 0 for an inner node
  };
  const std::vector<Node>& nodes() const { return m_nodes; }
  /// The triangles (as given to the constructor) in leaf order.
  const std::vector<int>& triangle_order() const { return m_order; }

 private:
  int build(int first, int count, const std::vector<Eigen::Vector3d>& centroids);
  std::vector<Node> m_nodes;
  std::vector<int> m_order;
};

/// The triangle nearest to a point, and where on it.
struct NearestTriangle {
  int triangle = -1;            ///< as given to the constructor
  Eigen::Vector3d barycentric;  ///< of the nearest point, on the triangle's corners in order
  double distance_m2 = 0.0;     ///< squared distance from the point to it (m²)
};

/// One pose of a TriangleBvhShape: its boxes refitted to corners.
class TriangleBvh {
 public:
  /// The hierarchy of `shape` around `corners_m` (three per triangle, in the order given to the
  /// shape; the same triangles the shape was built from, at any pose), which it keeps.
  TriangleBvh(std::shared_ptr<const TriangleBvhShape> shape,
              std::vector<Eigen::Vector3d> corners_m);

  /// The corners it was given (m).
  const std::vector<Eigen::Vector3d>& corners() const { return m_corners; }
  /// The box of every corner (its root's; empty without triangles).
  const Eigen::AlignedBox3d& bounds() const { return m_bounds; }

  /// The triangle nearest to x_m (Ericson 2005, "Real-Time Collision Detection", 5.1.5 for the
  /// point on a triangle); ties go to the first found. Not for x_m with a non-finite coordinate.
  NearestTriangle nearest(const Eigen::Vector3d& x_m) const;

  /// Calls visit(triangle) for every triangle whose box the segment from `from_m` to `to_m` may
  /// meet (a superset of the triangles it meets: the caller decides exactly).
  template <class Visit>
  void for_each_near_segment(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                             Visit&& visit) const;

 private:
  bool segment_may_meet(int node, const Eigen::Vector3d& from_m,
                        const Eigen::Vector3d& direction_m) const;

  std::shared_ptr<const TriangleBvhShape> m_shape;
  std::vector<Eigen::AlignedBox3d> m_boxes;  ///< per node
  std::vector<Eigen::Vector3d> m_corners;    ///< three per triangle (m)
  Eigen::AlignedBox3d m_bounds;              ///< of every corner (m)
  /// how much the segment test widens each box (m): far above its round-off, far below any mesh
  double m_slack_m = 0.0;
};

template <class Visit>
void TriangleBvh::for_each_near_segment(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                                        Visit&& visit) const {
  const std::vector<TriangleBvhShape::Node>& nodes = m_shape->nodes();
  const std::vector<int>& order = m_shape->triangle_order();
  const Eigen::Vector3d direction_m = to_m - from_m;
  int stack[128];  // depth-first: at most one pending sibling per level
  int size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const int n = stack[--size];
    if (!segment_may_meet(n, from_m, direction_m)) continue;
    const TriangleBvhShape::Node& node = nodes[n];
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k) visit(order[k]);
    } else {
      stack[size++] = node.second_child;
      stack[size++] = n + 1;
    }
  }
}

}  // namespace tissu
