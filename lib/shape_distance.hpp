#pragma once
/// \file
/// How far apart two runs of the same cloth are, whatever their meshes: the same material point is
/// found on both and its current positions compared; or, whichever material point is where, how
/// far each surface is from the other. CGAL-free header.

#include <vector>

#include "topology/indexed_mesh.hpp"

namespace tissu {

/// A cloth surface at one instant with the material (rest) coordinates of each vertex.
struct MaterialSurface {
  IndexedMesh current;                  ///< current positions (m); triangles or quads
  std::vector<Eigen::Vector3d> rest_m;  ///< #V material coordinates (m), the same vertex order
};

struct ShapeDistance {
  double mean_m = 0.0;  ///< mean over the compared points (m)
  double max_m = 0.0;   ///< largest (m)
  int points = 0;       ///< vertices of the reference compared
};

/// For every vertex of `reference`, the distance between its current position and the current
/// position of the same material point on `other`: the point is located on the nearest of
/// `other`'s triangles in rest space (quads are split along their first diagonal) and its position
/// interpolated barycentrically. A point that several of `other`'s triangles hold as nearly (to
/// 1 nm) at different places, as both lips of a tear do, is compared with the nearest of them.
/// Both surfaces must share their rest space (the same cloth at two resolutions, torn or not).
/// Throws std::invalid_argument when `other` has no face or the sizes disagree.
ShapeDistance material_point_distance(const MaterialSurface& other,
                                      const MaterialSurface& reference);

/// The current position on `other` of each material point of `rest_points_m` (m), located as
/// material_point_distance() locates them; where several triangles hold a point as nearly (both
/// lips of a tear), the one whose point is nearest `near_m`'s (#rest_points, m) when given, else
/// the first. Throws std::invalid_argument when `other` has no face or the sizes disagree.
std::vector<Eigen::Vector3d> material_point_positions(
    const MaterialSurface& other, const std::vector<Eigen::Vector3d>& rest_points_m,
    const std::vector<Eigen::Vector3d>* near_m = nullptr);

/// How far two surfaces are from each other as shapes, whichever material point lies where: the
/// distance from each vertex of one to the nearest point of the other's faces, both ways (the
/// symmetric Chamfer distance over vertices). `mean_m` is the mean of the two directions' means,
/// `max_m` the largest (the Hausdorff distance over vertices), `points` the vertices of both. A
/// fold that falls the other way, or cloth that slid along itself, counts only by how much the
/// surface moved, not by how far its material points travelled. Throws MeshError (naming the
/// element) when either surface has no face to measure against.
ShapeDistance surface_distance_between(const IndexedMesh& a, const IndexedMesh& b);

}  // namespace tissu
