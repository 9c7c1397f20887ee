#pragma once
/// \file
/// A rectangular grid of triangles or quads as an indexed mesh. CGAL-free.

#include "topology/grid_options.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// The grid of `options`, faces counter-clockwise around u x v. Throws std::invalid_argument on
/// non-positive sizes or cell counts, or axes that are not orthonormal.
IndexedMesh make_grid_mesh(const GridOptions& options);

/// Initial positions of the grid's vertices: the rest positions, or, with options.pleats > 0,
/// the cloth gathered into that many sine-shaped pleats across gathered_width, the amplitude
/// chosen so that the pleated width has the cloth's full arc length.
std::vector<Eigen::Vector3d> grid_initial_positions(const GridOptions& options);

}  // namespace tissu
