#pragma once
/// \file
/// Triangle meshes of the scenario's obstacles, for drawing them. CGAL-free.

#include <optional>
#include <vector>

#include "solver/collision/obstacle.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// Around-the-axis segments of sphere and capsule meshes; each hemisphere has a quarter as many
/// latitude bands. 64 keeps the silhouette of a sphere filling a 720-pixel-high image within
/// about half a pixel of a circle: the chord sag is r (1 - cos(pi / 64)) ~ 1.2e-3 r.
inline constexpr int obstacle_mesh_segments = 64;

/// A closed triangle mesh of `obstacle`'s surface where it is at `time_s` (its place at t = 0
/// moved by motion.pose(time_s)), faces counter-clockwise seen from outside, every vertex on the
/// surface (a mesh obstacle: its triangles, an animated one's at `time_s`):
/// - sphere: a UV sphere of `obstacle_mesh_segments` meridians and poles at +-z;
/// - capsule: a cylinder around the axis capped by two such hemispheres;
/// - box: 8 corners, 12 triangles, rotated by `rotation`.
/// A plane is unbounded and gives an empty mesh (see ground_height_m). A capsule whose ends
/// coincide is meshed as a sphere.
IndexedMesh obstacle_mesh(const Obstacle& obstacle, double time_s);

/// The height (z, m) at `time_s` of the highest plane among `obstacles` whose normal is +z (a
/// floor the renderer can draw as its ground), or nothing when there is none. Planes of other
/// normals (walls, slopes, ceilings) are ignored.
std::optional<double> ground_height_m(const std::vector<Obstacle>& obstacles, double time_s);

}  // namespace tissu
