#pragma once
/// \file
/// After a topological edit: rest areas, masses and springs recomputed around what changed only
/// (the course's second step of mesh refinement: neighbourhoods, masses and stiffnesses).

#include <Eigen/Core>
#include <vector>

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Recomputes the rest area of every face in `faces` (one dart each), the lumped mass of every
/// vertex of those faces (from all its incident faces), and the three spring slots of every dart
/// of those faces and of the darts across their edges.
void update_around_faces(ClothComplex& lcc, const std::vector<Dart_handle>& faces,
                         const SpringSettings& settings);

/// Points the attribute of every edge of the face of `face` at a dart of that face. CGAL 5.5's
/// remove_cell<0> merges the two edges at the removed vertex into one attribute but leaves that
/// attribute's dart on an erased dart (it re-points the face attributes only).
void repoint_edge_attributes(ClothComplex& lcc, Dart_handle face);

/// Linear momentum sum m v of the unpinned particles among `vertices` (kg m/s).
Eigen::Vector3d free_momentum(const std::vector<Vertex_handle>& vertices);

/// Gives the unpinned particles among `vertices` one common velocity change, so that their linear
/// momentum becomes `momentum_kg_m_per_s` (a pinned particle's momentum is its handle's). Nothing
/// when none is free.
void set_free_momentum(const std::vector<Vertex_handle>& vertices,
                       const Eigen::Vector3d& momentum_kg_m_per_s);

}  // namespace tissu
