#pragma once
/// \file
/// The cloth's current surface as an indexed mesh, for output and comparison.

#include "topology/cloth_complex.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// Vertices at their current positions, numbered by their particle index from the last compile;
/// one polygon per face (quads stay quads), oriented as in the complex, with the UV of each corner
/// (IndexedMesh::face_uvs) when the cloth carries its mesh's UVs (has_corner_uvs).
IndexedMesh current_mesh(const ClothComplex& lcc);

/// Material coordinates of the particles (m), in the vertex order of current_mesh.
std::vector<Eigen::Vector3d> rest_positions(const ClothComplex& lcc);

}  // namespace tissu
