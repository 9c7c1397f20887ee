#pragma once
/// \file
/// Bisects an edge of a triangle cloth and keeps the mesh conforming.

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Splits the edge of `dart` at its midpoint and joins the new vertex to the opposite corner of
/// each adjacent triangle (Rivara's longest-edge bisection step when `dart` is a longest edge): no
/// hanging node is left. The new particle takes the midpoint of the edge's positions, velocities
/// and material coordinates, and is pinned when both ends are (a clamped edge); since each
/// half-triangle then lumps rho A / 6 onto its corners and 2 x_mid = x_a + x_b, the total mass,
/// linear momentum and centre of mass are unchanged. Rest areas, masses and springs are recomputed
/// on the two to four faces around it. In each face, the new corner's UV is the midpoint of that
/// face's UVs at the edge's ends, and the cut edge's corners take the UVs the face had there
/// (corner_uvs.hpp). Requires the edge's faces to be triangles (throws
/// std::invalid_argument otherwise). Returns a dart starting at the new vertex.
Dart_handle split_edge(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings);

}  // namespace tissu
