#include "solver/collision/triangle_bvh.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace tissu {
namespace {

constexpr int leaf_size = 4;

/// Barycentric coordinates of the point of triangle abc nearest to p, by the Voronoi region of
/// the triangle that p projects into (Ericson 2005, 5.1.5): a corner, an edge or the inside.
Eigen::Vector3d nearest_barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double scale = 1.0 / (va + vb + vc);
  const double v = vb * scale, w = vc * scale;
  return {1.0 - v - w, v, w};
}

}  // namespace

TriangleBvhShape::TriangleBvhShape(const std::vector<Eigen::Vector3d>& corners_m) {
  const int count = static_cast<int>(corners_m.size() / 3);
  std::vector<Eigen::Vector3d> centroids(count);
  for (int t = 0; t < count; ++t) {
    centroids[t] = (corners_m[3 * t] + corners_m[3 * t + 1] + corners_m[3 * t + 2]) / 3.0;
  }
  m_order.resize(count);
  std::iota(m_order.begin(), m_order.end(), 0);
  m_nodes.reserve(2 * (count / leaf_size + 1));
  if (count > 0) build(0, count, centroids);
}

int TriangleBvhShape::build(int first, int count, const std::vector<Eigen::Vector3d>& centroids) {
  const int index = static_cast<int>(m_nodes.size());
  m_nodes.emplace_back();
  if (count <= leaf_size) {
    m_nodes[index].first = first;
    m_nodes[index].count = count;
    return index;
  }
  Eigen::AlignedBox3d box;
  for (int k = first; k < first + count; ++k) box.extend(centroids[m_order[k]]);
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  const int half = count / 2;
  const auto begin = m_order.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [&centroids, axis](int s, int t) {
    return centroids[s][axis] < centroids[t][axis];
  });
  build(first, half, centroids);
  const int second = build(first + half, count - half, centroids);
  m_nodes[index].second_child = second;
  return index;
}

TriangleBvh::TriangleBvh(std::shared_ptr<const TriangleBvhShape> shape,
                         std::vector<Eigen::Vector3d> corners_m)
    : m_shape(std::move(shape)), m_corners(std::move(corners_m)) {
  const std::vector<int>& order = m_shape->triangle_order();
  assert(m_corners.size() == 3 * order.size());
  const std::vector<TriangleBvhShape::Node>& nodes = m_shape->nodes();
  m_boxes.resize(nodes.size());
  // children follow their parent: refit from the last node back to the root
  for (int n = static_cast<int>(nodes.size()) - 1; n >= 0; --n) {
    const TriangleBvhShape::Node& node = nodes[n];
    Eigen::AlignedBox3d& box = m_boxes[n];
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        for (int c = 0; c < 3; ++c) box.extend(m_corners[3 * order[k] + c]);
      }
    } else {
      box = m_boxes[n + 1].merged(m_boxes[node.second_child]);
    }
  }
  if (!m_boxes.empty()) {
    m_bounds = m_boxes.front();
    m_slack_m = 1e-9 * (m_bounds.diagonal().norm() + m_bounds.max().cwiseAbs().maxCoeff() +
                        m_bounds.min().cwiseAbs().maxCoeff());
  }
}

NearestTriangle TriangleBvh::nearest(const Eigen::Vector3d& x_m) const {
  const std::vector<TriangleBvhShape::Node>& nodes = m_shape->nodes();
  const std::vector<int>& order = m_shape->triangle_order();
  NearestTriangle best;
  best.distance_m2 = std::numeric_limits<double>::infinity();
  if (nodes.empty()) return best;
  std::pair<int, double> stack[128];  // (node, squared distance to its box), nearer on top
  int size = 0;
  stack[size++] = {0, m_boxes[0].squaredExteriorDistance(x_m)};
  while (size > 0) {
    const auto [n, box_m2] = stack[--size];
    if (box_m2 >= best.distance_m2) continue;
    const TriangleBvhShape::Node& node = nodes[n];
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        const int t = order[k];
        const Eigen::Vector3d& a = m_corners[3 * t];
        const Eigen::Vector3d& b = m_corners[3 * t + 1];
        const Eigen::Vector3d& c = m_corners[3 * t + 2];
        const Eigen::Vector3d l = nearest_barycentric(x_m, a, b, c);
        const double m2 = (l[0] * a + l[1] * b + l[2] * c - x_m).squaredNorm();
        if (m2 < best.distance_m2) best = {t, l, m2};
      }
      continue;
    }
    const int first = n + 1, second = node.second_child;
    const double first_m2 = m_boxes[first].squaredExteriorDistance(x_m);
    const double second_m2 = m_boxes[second].squaredExteriorDistance(x_m);
    if (first_m2 <= second_m2) {
      stack[size++] = {second, second_m2};
      stack[size++] = {first, first_m2};
    } else {
      stack[size++] = {first, first_m2};
      stack[size++] = {second, second_m2};
    }
  }
  return best;
}

bool TriangleBvh::segment_may_meet(int node, const Eigen::Vector3d& from_m,
                                   const Eigen::Vector3d& direction_m) const {
  const Eigen::AlignedBox3d& box = m_boxes[node];
  double enter = 0.0, leave = 1.0;  // the segment's parameters inside every slab so far
  for (int axis = 0; axis < 3; ++axis) {
    const double low = box.min()[axis] - m_slack_m, high = box.max()[axis] + m_slack_m;
    const double d = direction_m[axis];
    if (d == 0.0) {
      if (from_m[axis] < low || from_m[axis] > high) return false;
      continue;
    }
    double t0 = (low - from_m[axis]) / d, t1 = (high - from_m[axis]) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return false;
  }
  return true;
}

}  // namespace tissu
