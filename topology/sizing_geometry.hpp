#pragma once
/// \file
/// What the sizing fields read off the cloth (sizing_field.hpp, the isotropic field bisection
/// follows, and sizing_metric.hpp, the anisotropic one remeshing follows): dihedral angles now and
/// at rest, and the obstacles' tangent planes under the particles.

#include <Eigen/Geometry>
#include <array>
#include <unordered_map>

#include "topology/cloth_complex.hpp"
#include "topology/sizing_field.hpp"

namespace tissu {

/// The three corners of the dart's triangle, from the dart's origin, as read by `at`.
template <class Position>
std::array<Eigen::Vector3d, 3> corners(const ClothComplex& lcc, Dart_const_handle d, Position at) {
  return {at(d), at(lcc.next(d)), at(lcc.next(lcc.next(d)))};
}

/// Signed angle (rad) between the normals of the faces of `d` and of its twin about the edge
/// a -> b of `d`, with the corners of each face from `at`: 0 flat, positive folding one way.
template <class Position>
double signed_dihedral(const ClothComplex& lcc, Dart_const_handle d, Position at) {
  const auto f = corners(lcc, d, at);
  const auto g = corners(lcc, lcc.opposite<2>(d), at);
  const Eigen::Vector3d n1 = (f[1] - f[0]).cross(f[2] - f[0]);
  const Eigen::Vector3d n2 = (g[1] - g[0]).cross(g[2] - g[0]);
  const Eigen::Vector3d edge = f[1] - f[0];
  const double length = edge.norm();
  if (!(length > 0.0) || !(n1.squaredNorm() > 0.0) || !(n2.squaredNorm() > 0.0)) return 0.0;
  return std::atan2(n1.cross(n2).dot(edge) / length, n1.dot(n2));
}

/// `angle` wrapped into [-pi, pi] (rad).
double wrapped(double angle);

/// An interior edge's signed dihedral angle relative to rest (rad): wrapped(theta - theta0), with
/// theta now and at x + lookahead v (ahead_rad 0 when lookahead_s is 0). The same from either of
/// the edge's darts.
struct EdgeTurn {
  double now_rad = 0.0;
  double ahead_rad = 0.0;
};

/// The turn of the interior edge of dart `d` (not free in dimension 2).
EdgeTurn edge_turn(const ClothComplex& lcc, Dart_const_handle d, double lookahead_s);

/// The tangent plane of the obstacle nearest a particle: a point on it and its unit normal, and the
/// obstacle's thickness (m).
struct NearestPlane {
  Eigen::Vector3d point;
  Eigen::Vector3d normal;
  double thickness_m = 0.0;
};

/// Each particle's nearest plane, by its vertex attribute's address.
using NearestPlanes = std::unordered_map<const void*, NearestPlane>;

/// The nearest plane of every particle among `inputs`' obstacles (which must be given).
NearestPlanes nearest_planes(const ClothComplex& lcc, const SizingInputs& inputs);

/// ARCSim's obstacle metric asks for an edge L <= sqrt(2 R t) on cloth lying on a surface of
/// radius R at the contact thickness t (its heights grow as d^2 / 2R from a corner at t, so
/// |grad h|^2 / h^2 ~ L^2 / (4 R^2 t^2)). What the mesh needs is that its faces' chords stay within
/// that thickness: the sagitta L^2 / (8 R) of a face of longest edge L (circumradius L / 2 for the
/// right triangles of bisection) at most t, so L <= sqrt(8 R t), twice as long: the metric / 16.
/// On the drape this keeps 1,385 particles where the metric alone made 1,958, and the ball does
/// not show through (docs/benchmarks.md, "the drape at equal steps").
constexpr double sagitta_scale = 1.0 / 16.0;

/// The obstacle term as a tensor in material coordinates (1/m^2): ARCSim's obstacle metric, the
/// mean over the triangle's corners v of g_v g_v^T / h_v(v)^2, h_v the heights of the corners
/// above v's nearest plane (at least the obstacle's thickness at v), g_v their gradient over the
/// face in rest space, times sagitta_scale. Its trace is the isotropic field's obstacle term.
Eigen::Matrix3d obstacle_metric(const ClothComplex& lcc, Dart_const_handle d,
                                const NearestPlanes& planes);

/// Each term's share of a face's sizing (1/m^2): for the isotropic field, the largest over its
/// edges for the edge terms; for the metric, each term's trace.
struct TermShares {
  double curvature = 0.0;
  double velocity = 0.0;  ///< what looking ahead adds to the curvature term
  double strain = 0.0;
  double obstacles = 0.0;
};

/// The term with the largest share, or the maximum edge length when its floor (1/m^2) is above
/// them all.
SizingTerm largest_share(const TermShares& shares, double floor_per_m2);

}  // namespace tissu
