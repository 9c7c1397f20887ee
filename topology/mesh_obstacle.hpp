#pragma once
/// \file
/// A triangle mesh as an obstacle's surface, queried through CGAL's AABB tree.

#include <memory>

#include "solver/collision/obstacle.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// The distance field of `mesh` (quads are cut in two), for an Obstacle of shape mesh. A closed
/// mesh (every edge shared by two faces) must face outwards (counter-clockwise seen from
/// outside): its distance is signed, negative inside, the sign taken from the nearest face's
/// normal, which is exact except near concave edges. An open mesh (a sheet, a table top) is a
/// two-sided shell: the distance is unsigned and the normal points from the surface to the point.
/// Throws MeshError if `mesh` fails validate_indexed_mesh.
std::shared_ptr<const SurfaceQuery> make_mesh_surface(const IndexedMesh& mesh);

}  // namespace tissu
