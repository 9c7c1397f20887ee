#pragma once
/// \file
/// The constant part of Projective Dynamics' global step for springs, cached between steps:
/// (M/h^2 + L) p = M/h^2 y + J d, L the spring Laplacian weighted by the stiffnesses (applied to
/// x, y and z alike), pinned particles eliminated (Liu et al. 2013, "Fast simulation of
/// mass-spring systems"; Bouaziz et al. 2014, "Projective dynamics").

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "solver/pd/particle_coloring.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Row i of the global system for a free particle i, with c_i the right-hand side of the step:
///   a_i p_i - sum over springs (i, j) of s_ij p_j = c_i,   a_i = m_i/h^2 + sum s_ij  (kg/s^2),
/// where pinned neighbours j enter with their prescribed positions. Neighbour lists follow
/// model.incidence (one entry per spring end, so two springs joining i and j give two entries).
/// Rebuilt by update_pd_system() only when the model (its identity) or the time step changes.
struct PdSystem {
  std::uint64_t built_for_model = 0;  ///< SpringModel::identity it was built from (0 = none)
  double built_time_step = 0.0;       ///< h (s)
  std::uint64_t generation = 0;       ///< unique per build (0 = never built)

  std::vector<int> neighbour_offsets;   ///< #P+1 = model.incidence.offsets
  std::vector<int> neighbours;          ///< #incidences other end j of each spring of i
  std::vector<double> weights;          ///< #incidences stiffness s_ij (N/m)
  Eigen::VectorXd inertia;              ///< #P m_i / h^2 (kg/s^2)
  Eigen::VectorXd diagonal;             ///< #P a_i = m_i/h^2 + sum s_ij (kg/s^2)
  std::vector<std::uint8_t> pinned;     ///< #P 1 if the particle is prescribed (not solved)
  std::vector<int> free_index;          ///< #P row among the free particles, -1 if pinned
  std::vector<int> free_particles;      ///< #F particle ids of the free particles, ascending
  ParticleColoring coloring;            ///< colouring of all particles (all spring kinds)
  std::vector<int> free_color_offsets;  ///< #colours+1 offsets into free_color_order
  std::vector<int> free_color_order;    ///< #F free particles by colour: colour c is
                                        ///< [free_color_offsets[c], free_color_offsets[c+1])
  /// Block Gauss-Seidel: the free particles cut into blocks of consecutive ids (block b is
  /// free_particles[block_offsets[b], block_offsets[b+1])), and the blocks coloured so that no
  /// spring joins two blocks of one colour.
  std::vector<int> block_offsets;   ///< #blocks+1
  ParticleColoring block_coloring;  ///< colouring of the blocks (block ids, not particle ids)
  /// Gershgorin bound on the spectral radius of the Jacobi iteration matrix D^-1 (D - A):
  /// max over free i of sum s_ij / a_i, < 1 (dimensionless).
  double jacobi_radius_bound = 0.0;
  std::vector<int> scratch;              ///< colouring scratch
  std::vector<int> block_of;             ///< #P block of each free particle, -1 if pinned (scratch)
  std::vector<int> block_graph_offsets;  ///< #blocks+1 (scratch)
  std::vector<int> block_graph_neighbours;  ///< blocks sharing a spring with each block (scratch)
};

/// Makes `system` describe `model` at time step h (s): rebuilds it (O(#P + #S), allocating) if it
/// was built for another model (SpringModel::identity) or another h, otherwise leaves it as is.
/// Returns true if it rebuilt. The model must be finalized.
bool update_pd_system(const SpringModel& model, double time_step_s, PdSystem& system);

}  // namespace tissu
