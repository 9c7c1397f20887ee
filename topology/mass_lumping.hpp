#pragma once
/// \file
/// Lumped particle masses of the cloth complex, from the faces' rest areas and densities.

#include "topology/cloth_complex.hpp"

namespace tissu {

/// Lumped masses (course: m = sum_i m_i): each face gives density x rest area / (its vertex count)
/// to each of its vertices, so the total is density x total rest area.
void lump_masses(ClothComplex& lcc);

/// Sets the mass of `vertex` to its share of each incident face: sum of density x rest area /
/// (vertex count of the face), the per-vertex form of lump_masses().
void lump_vertex_mass(ClothComplex& lcc, Vertex_handle vertex);

/// Sum of particle masses (kg), compensated (solver/compensated_sum.hpp).
double complex_total_mass(const ClothComplex& lcc);

/// Sum over faces of areal density x rest area (kg), compensated: what the particle masses must
/// add up to.
double complex_expected_mass(const ClothComplex& lcc);

}  // namespace tissu
