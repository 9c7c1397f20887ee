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
/// Particle::index_at_last_compile), one structural and one bending spring per edge whose slots are
/// present, one shear spring per present quad diagonal, the faces as triangles (quads cut along
/// the diagonal from their first dart). Reads positions and velocities into the state.
CompiledCloth compile(ClothComplex& lcc, double time_s = 0.0);

/// Copies positions and velocities of `state` into the vertices of the complex it was compiled
/// from.
void write_back(const CompiledCloth& compiled, const State& state, ClothComplex& lcc);

/// Edits the complex of a compiled cloth and recompiles it, keeping the state (MuJoCo's
/// mj_recompile, "recompile, preserving the state"): writes cloth.state into `lcc`, so that the
/// edit sees the current positions and velocities; calls `edit(lcc)`, which returns whether it
/// changed the complex; if it did, compiles `lcc` again at cloth.state.time. The new model has a
/// new identity (SpringModel::identity), so the caches of any workspace that steps it rebuild by
/// themselves. Returns what `edit` returned. Every topological edit of a running cloth goes
/// through here: cloth.particle_vertices and cloth.spring_darts are stale once `edit` has run.
template <class Edit>
bool edit_and_recompile(ClothComplex& lcc, CompiledCloth& cloth, Edit&& edit) {
  write_back(cloth, cloth.state, lcc);
  if (!edit(lcc)) return false;
  cloth = compile(lcc, cloth.state.time);
  return true;
}

}  // namespace tissu
