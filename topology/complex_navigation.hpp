#pragma once
/// \file
/// Walking the cloth complex: the darts around a vertex, the vertex after an edge, the vertex
/// nearest a material point.

#include <Eigen/Core>
#include <vector>

#include "topology/cloth_complex.hpp"

namespace tissu {

/// The darts starting at `vertex`: one per incident face.
std::vector<Dart_handle> darts_leaving(ClothComplex& lcc, Vertex_handle vertex);

/// The vertex that follows the dart's edge in the dart's face (the apex for a triangle).
Vertex_handle vertex_after_edge(ClothComplex& lcc, Dart_handle dart);

/// The vertex whose material coordinates are nearest `rest_point_m` (the first in container order
/// among equally near ones). The complex must have a vertex.
Vertex_handle nearest_vertex(ClothComplex& lcc, const Eigen::Vector3d& rest_point_m);

}  // namespace tissu
