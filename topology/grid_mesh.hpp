#pragma once
/// \file
/// A rectangular grid of triangles or quads as an indexed mesh. CGAL-free.

#include "topology/grid_options.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// The grid of `options`, faces counter-clockwise around u x v. Throws std::invalid_argument on
/// non-positive sizes or cell counts, or axes that are not orthonormal.
IndexedMesh make_grid_mesh(const GridOptions& options);

}  // namespace tissu
