#pragma once
/// \file
/// A triangle mesh as an obstacle's surface: distances through CGAL's AABB tree, inside and
/// outside by the generalised winding number.

#include <memory>

#include "solver/collision/obstacle.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// What make_mesh_surface found in the faces it was given.
struct ObstacleMeshReport {
  int triangles = 0;         ///< kept, after cutting polygons into fans
  int duplicate_faces = 0;   ///< dropped: the same vertices in the same cyclic order as another
  int degenerate_faces = 0;  ///< dropped: only repeated vertices or zero area
  bool closed = false;       ///< every directed edge matched by its reverse: inside is defined
};

/// The distance field of an obstacle mesh, which need not be a manifold: a triangle soup of
/// several parts that touch or overlap is accepted (only the cloth must be a manifold).
/// - Polygons are cut into fans from their first vertex (exact for triangles, quads and convex
///   polygons); exact duplicate faces and degenerate faces are dropped and counted in `report`.
/// - A closed mesh (every directed edge a->b matched by an edge b->a, so parts may share edges)
///   must face outwards: its distance is signed, negative where the winding number exceeds 1/2
///   (inside any of its parts). The winding number decides, not the nearest face's normal,
///   because near a vertex or an edge that face can point away from the point (a pyramid's apex,
///   a concave notch), and because soups have no single nearest feature to take a pseudo-normal
///   from where parts meet.
/// - An open mesh (a sheet, a table top, a scan with holes) is a two-sided shell: the distance
///   is unsigned and the normal points from the surface to the point.
/// Throws MeshError naming the element when the mesh cannot be queried: no faces, an index out
/// of range, a non-finite coordinate, a face of fewer than 3 vertices, or only degenerate faces.
std::shared_ptr<const SurfaceQuery> make_mesh_surface(const IndexedMesh& mesh,
                                                      ObstacleMeshReport* report = nullptr);

}  // namespace tissu
