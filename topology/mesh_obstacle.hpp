#pragma once
/// \file
/// A triangle mesh as an obstacle's surface, fixed or animated: distances through a bounding-box
/// hierarchy (triangle_bvh.hpp), inside and outside by the generalised winding number.

#include <array>
#include <memory>
#include <vector>

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

/// The rays along which a closed mesh's crossings are counted: the six of the axes, each tilted
/// off it by a few degrees (meshes often have edges along the axes), of few bits (a test can aim
/// them exactly at a vertex).
const std::array<Eigen::Vector3d, 6>& winding_ray_directions();

/// The distance field of an obstacle mesh, which need not be a manifold: a triangle soup of
/// several parts that touch or overlap is accepted (only the cloth must be a manifold).
/// - Polygons are cut into fans from their first vertex (exact for triangles, quads and convex
///   polygons); exact duplicate faces and degenerate faces are dropped and counted in `report`.
/// - A closed mesh (every directed edge a->b matched by an edge b->a, so parts may share edges)
///   must face outwards: its distance is signed, negative where the winding number exceeds 1/2
///   (inside any of its parts). The winding number decides, not the nearest face's normal,
///   because near a vertex or an edge that face can point away from the point (a pyramid's apex,
///   a concave notch), and because soups have no single nearest feature to take a pseudo-normal
///   from where parts meet. A closed mesh's winding number is an integer: the signed count of
///   the faces a ray from the point crosses (+1 leaving by a face's front, -1 entering), the
///   ray being the shortest way out of the mesh's box among winding_ray_directions(), and the
///   next one where CGAL's exact predicates find it through an edge or a vertex. With all six so,
///   the solid angles are summed (winding_number.hpp). Counting crossings halved a signed
///   distance's cost near a closed sphere of 960 to 16,128 triangles (docs/benchmarks.md).
/// - An open mesh (a sheet, a table top, a scan with holes) is a two-sided shell: the distance
///   is unsigned and the normal points from the surface to the point.
/// Throws MeshError naming the element when the mesh cannot be queried: no faces, an index out
/// of range, a non-finite coordinate, a face of fewer than 3 vertices, or only degenerate faces.
std::shared_ptr<const SurfaceQuery> make_mesh_surface(const IndexedMesh& mesh,
                                                      ObstacleMeshReport* report = nullptr);

/// `mesh`'s faces in groups connected through shared vertices (its parts: a torso, an arm), each
/// group a mesh with all of `mesh`'s vertices (so that an animation's positions fit every part).
/// Where closed parts overlap, a point inside one is led out by the nearest face of the soup,
/// which may be buried inside another part; queried alone, each part leads it out of itself.
std::vector<IndexedMesh> separate_parts(const IndexedMesh& mesh);

/// A mesh's vertex positions at increasing times: an animation (a body's point cache, a sequence
/// of meshes of the same connectivity).
struct MeshSamples {
  std::vector<double> times_s;
  std::vector<std::vector<Eigen::Vector3d>> vertices_m;  ///< per sample, one per mesh vertex
};

/// An animated obstacle mesh: `mesh`'s faces, checked and cleaned as make_mesh_surface does (with
/// the first sample's positions, which replace `mesh`'s), their corners at `samples`' positions,
/// interpolated linearly in time between samples and held before the first and after the last.
/// Its surface at an instant is built when first asked for (the hierarchy over its triangles,
/// built once from the first sample, refitted to the instant's corners), and the last few are kept:
/// a run asks for each step's end twice (as the next step's start), and instants within 1e-9 s
/// count as one. Throws MeshError naming the sample (from 0) and the element: no sample, a time not
/// finite or not after the one before, a sample whose vertex count differs from the mesh's or with
/// a non-finite coordinate, a kept triangle of no area in some sample, or anything
/// make_mesh_surface refuses.
std::shared_ptr<const SurfaceAnimation> make_mesh_animation(const IndexedMesh& mesh,
                                                            MeshSamples samples,
                                                            ObstacleMeshReport* report = nullptr);

}  // namespace tissu
