#pragma once
/// \file
/// Smooth per-vertex normals of a polygon mesh.

#include <Eigen/Core>
#include <vector>

#include "topology/indexed_mesh.hpp"

namespace tissu {

/// The vector area of polygon `face` of `mesh`: 1/2 sum_i (p_i - p_0) x (p_(i+1) - p_0), normal
/// to the face by the right-hand rule on its vertex order, of length its area (m^2) when planar.
Eigen::Vector3d face_vector_area(const IndexedMesh& mesh, const std::vector<int>& face);

/// #V unit normals: at each vertex, the normalised sum of the vector areas of the faces around it
/// (area-weighted face normals). A vertex in no face, or whose faces cancel, gets the zero vector.
/// Face vertex ids must be in range.
std::vector<Eigen::Vector3f> vertex_normals(const IndexedMesh& mesh);

}  // namespace tissu
