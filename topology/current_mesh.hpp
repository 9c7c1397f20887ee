#pragma once
/// \file
/// The cloth's current surface as an indexed mesh, for output.

#include "topology/cloth_complex.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// Vertices at their current positions, numbered by their particle index from the last compile;
/// one polygon per face (quads stay quads), oriented as in the complex.
IndexedMesh current_mesh(const ClothComplex& lcc);

}  // namespace tissu
