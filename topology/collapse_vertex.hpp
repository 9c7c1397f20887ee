#pragma once
/// \file
/// Removes a particle that refinement made by collapsing one of its edges onto the neighbour at
/// the other end: the coarsening step of anisotropic remeshing (Narain, Samii & O'Brien 2012,
/// section 5.3), which, unlike undoing a bisection, works whatever flips have done around it.

#include <optional>
#include <string>
#include <vector>

#include "topology/cloth_complex.hpp"
#include "topology/retriangulation.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// The triangles, in material coordinates, that collapsing `removed` onto `kept` would leave where
/// the faces around `removed` are: each (removed, w_i, w_i+1) of them not touching `kept` becomes
/// (kept, w_i, w_i+1). Empty when collapse_refusal() refuses.
std::vector<RestTriangle> triangles_after_collapse(const ClothComplex& lcc,
                                                   Vertex_const_handle removed,
                                                   Vertex_const_handle kept);

/// Why `removed` cannot be collapsed onto its neighbour `kept`, or nothing when it can:
/// - `removed` is a particle of the input mesh, pinned or to be pinned, or on a crack;
/// - the faces around it are not all triangles, or do not form one fan (a vertex torn into two);
/// - it is inside the cloth with three neighbours, or on the border with one face, or on the
///   border with `kept` inside (it may only slide along the border);
/// - `kept` is already joined to a vertex the collapse would join it to;
/// - an edge at `removed` is a UV seam;
/// - the new triangles do not tile the faces' rest region (keeps_rest_region(): in material
///   coordinates, a fold-over, or a border that is not straight at `removed`, or a curved rest
///   shape), which would change the rest area and the masses.
std::optional<std::string> collapse_refusal(const ClothComplex& lcc, Vertex_const_handle removed,
                                            Vertex_const_handle kept);

/// Collapses `removed` onto `kept` (collapse_refusal() must give nothing: throws
/// std::invalid_argument otherwise). `kept` does not move. The faces around `removed` become the
/// fan from `kept` over the same rest region: the total rest area, and so the total mass, is
/// unchanged; the new faces take the rest-area-weighted mean of the old ones' input areas
/// (FaceRest::input_area) and their sizing, and rest areas, masses and springs are recomputed
/// around them. The removed particle's momentum is handed to the free neighbours, so that the
/// linear momentum of the free particles is unchanged.
void collapse_vertex(ClothComplex& lcc, Vertex_handle removed, Vertex_handle kept,
                     const SpringSettings& settings);

}  // namespace tissu
