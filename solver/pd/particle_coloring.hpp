#pragma once
/// \file
/// Graph colouring of the particles: no spring joins two particles of one colour, so that every
/// colour's particles can be updated by Gauss-Seidel at the same time.

#include <vector>

#include "solver/spring_model.hpp"

namespace tissu {

/// Particles grouped by colour. Two particles joined by a spring (of any kind) never share one.
struct ParticleColoring {
  std::vector<int> color;          ///< #P colour of each particle, in [0, color_count())
  std::vector<int> color_offsets;  ///< #colours+1, colour c is order[offsets[c], offsets[c+1])
  std::vector<int> order;          ///< #P particle ids by colour, ascending within a colour

  int color_count() const { return static_cast<int>(color_offsets.size()) - 1; }
};

/// Greedy colouring in particle order: each particle takes the smallest colour that none of its
/// already coloured spring neighbours has (Welsh & Powell's sequential greedy, without the degree
/// ordering), so at most max degree + 1 colours; a grid with structural, shear and bending springs
/// (degree 12) gets few. The course's red-black ordering is the two-colour case, exact only for
/// structural springs on a grid; Fratarcangeli et al. 2016 (Vivace) colour the general graph.
/// Deterministic. Uses model.incidence: call finalize_model() first. O(#P + #S).
ParticleColoring color_particles(const SpringModel& model);

/// Same colouring from compressed neighbour lists (neighbours of particle i are
/// neighbours[offsets[i], offsets[i+1]), duplicates allowed), written into `coloring`, reusing its
/// buffers. `marks` is scratch.
void color_particles(const std::vector<int>& offsets, const std::vector<int>& neighbours,
                     ParticleColoring& coloring, std::vector<int>& marks);

/// True if no spring of `model` joins two particles of one colour and every particle is coloured.
bool is_valid_coloring(const SpringModel& model, const ParticleColoring& coloring);

}  // namespace tissu
