#include "topology/winding_number.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace tissu {
namespace {

/// Leaves hold at most this many triangles: summing them exactly costs less than descending.
constexpr int leaf_size = 8;

}  // namespace

double solid_angle_sr(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& x) {
  const Eigen::Vector3d p = a - x, q = b - x, r = c - x;
  const double lp = p.norm(), lq = q.norm(), lr = r.norm();
  const double numerator = p.dot(q.cross(r));
  const double denominator = lp * lq * lr + p.dot(q) * lr + p.dot(r) * lq + q.dot(r) * lp;
  return 2.0 * std::atan2(numerator, denominator);
}

WindingNumberTree::WindingNumberTree(std::vector<Eigen::Vector3d> corners, double far_ratio)
    : m_corners(std::move(corners)), m_far_ratio(far_ratio) {
  const int triangles = static_cast<int>(m_corners.size() / 3);
  m_order.resize(triangles);
  for (int t = 0; t < triangles; ++t) m_order[t] = t;
  if (triangles > 0) build(0, triangles);
}

int WindingNumberTree::build(int first, int count) {
  const int id = static_cast<int>(m_nodes.size());
  m_nodes.emplace_back();
  Node node;
  node.first = first;
  node.count = count;
  // area vector and area-weighted centroid; a degenerate node falls back to the plain centroid
  Eigen::AlignedBox3d centroids;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero(), plain = Eigen::Vector3d::Zero();
  double area_m2 = 0.0;
  node.area_m2.setZero();
  for (int k = first; k < first + count; ++k) {
    const Eigen::Vector3d* c = &m_corners[3 * m_order[k]];
    const Eigen::Vector3d area = 0.5 * (c[1] - c[0]).cross(c[2] - c[0]);
    const Eigen::Vector3d centroid = (c[0] + c[1] + c[2]) / 3.0;
    node.area_m2 += area;
    weighted += area.norm() * centroid;
    plain += centroid;
    area_m2 += area.norm();
    centroids.extend(centroid);
  }
  node.centre_m =
      area_m2 > 0.0 ? Eigen::Vector3d(weighted / area_m2) : Eigen::Vector3d(plain / count);
  for (int k = first; k < first + count; ++k) {
    for (int i = 0; i < 3; ++i) {
      node.radius_m =
          std::max(node.radius_m, (m_corners[3 * m_order[k] + i] - node.centre_m).norm());
    }
  }
  if (count > leaf_size) {
    // split at the median centroid along the longest side of the centroids' box
    Eigen::Index axis = 0;
    centroids.sizes().maxCoeff(&axis);
    const auto centroid_along = [&](int t) {
      const Eigen::Vector3d* c = &m_corners[3 * t];
      return c[0][axis] + c[1][axis] + c[2][axis];
    };
    const int half = count / 2;
    std::nth_element(m_order.begin() + first, m_order.begin() + first + half,
                     m_order.begin() + first + count,
                     [&](int s, int t) { return centroid_along(s) < centroid_along(t); });
    node.left = build(first, half);
    node.right = build(first + half, count - half);
  }
  m_nodes[id] = node;
  return id;
}

double WindingNumberTree::triangle_solid_angle_sr(int triangle, const Eigen::Vector3d& x) const {
  const Eigen::Vector3d* c = &m_corners[3 * triangle];
  return solid_angle_sr(c[0], c[1], c[2], x);
}

double WindingNumberTree::winding_number(const Eigen::Vector3d& x) const {
  if (m_nodes.empty()) return 0.0;
  double omega_sr = 0.0;
  int stack[128];  // depth ~ log2(#triangles / leaf_size): far below this
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = m_nodes[stack[--top]];
    const Eigen::Vector3d to_centre = node.centre_m - x;
    const double distance_m = to_centre.norm();
    if (distance_m > m_far_ratio * node.radius_m) {
      omega_sr += node.area_m2.dot(to_centre) / (distance_m * distance_m * distance_m);
    } else if (node.left < 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        omega_sr += triangle_solid_angle_sr(m_order[k], x);
      }
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return omega_sr / (4.0 * std::numbers::pi);
}

double WindingNumberTree::exact_winding_number(const Eigen::Vector3d& x) const {
  double omega_sr = 0.0;
  for (int t = 0; t < static_cast<int>(m_corners.size() / 3); ++t) {
    omega_sr += triangle_solid_angle_sr(t, x);
  }
  return omega_sr / (4.0 * std::numbers::pi);
}

}  // namespace tissu
