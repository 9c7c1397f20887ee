#pragma once
/// \file
/// From the cloth complex to the solver's flat model, and back (MuJoCo's mj_compile pattern).

#include <vector>

#include "solver/spring_model.hpp"
#include "topology/cloth_complex.hpp"

namespace tissu {

/// The flat model and state of a complex, with the maps back to the complex's cells.
struct CompiledCloth {
  SpringModel model;
  State state;
  std::vector<Vertex_handle> particle_vertices;  ///< #P vertex of each particle
  std::vector<Dart_handle> spring_darts;         ///< #S a dart holding each spring
};

/// Compiles `lcc`: one particle per vertex (numbered in container order, stored back as
/// Particle::particle_index), one structural and one bending spring per edge whose slots are
/// present, one shear spring per present quad diagonal, the faces as triangles (quads cut along
/// the diagonal from their first dart). Reads positions and velocities into the state.
CompiledCloth compile(ClothComplex& lcc, double time_s = 0.0);

/// Copies positions and velocities of `state` into the vertices of the complex it was compiled
/// from.
void write_back(const CompiledCloth& compiled, const State& state, ClothComplex& lcc);

}  // namespace tissu
