#pragma once
/// \file
/// From an indexed mesh to a cloth complex with rest data, masses and springs.

#include "topology/cloth_complex.hpp"
#include "topology/indexed_mesh.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// Replaces `lcc` by the faces of `mesh`, sewn along shared edges. Positions are the mesh's;
/// material coordinates equal them (the mesh is its own rest shape); velocities are zero. Each
/// particle keeps its mesh vertex id as source_index; vertices no face uses are left out. The
/// mesh's texture coordinates, if it has some, go on the darts (CornerMechanics::uv, one per face
/// corner); a mesh without leaves every dart without. Rest
/// areas, masses and springs are then assigned (rest_geometry.hpp, mass_lumping.hpp,
/// spring_assignment.hpp).
/// Throws MeshError when validate_indexed_mesh rejects the mesh, or when the built complex fails
/// validity_problems (validity.hpp), checked in every build type.
void build_cloth_complex(const IndexedMesh& mesh, double areal_density_kg_per_m2,
                         const SpringSettings& springs, ClothComplex& lcc);

/// Moves every particle to positions[its source_index] (m), leaving the rest shape as it is.
/// Throws std::invalid_argument when `positions` has fewer entries than the input had vertices.
void place_particles(const std::vector<Eigen::Vector3d>& positions, ClothComplex& lcc);

}  // namespace tissu
