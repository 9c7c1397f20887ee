#pragma once
/// \file
/// The flat model the solver steps: compiled from the cloth complex (topology/compile.hpp), fixed
/// between two topological changes. Structure of arrays; every field states its shape and unit.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace tissu {

/// Role of a spring in the cloth (Provot 1995): along an edge, across a quad, across a hinge.
enum class SpringKind : std::uint8_t { structural = 0, shear = 1, bending = 2 };
inline constexpr int spring_kind_count = 3;

/// Compressed rows of the particle -> spring incidence, for deterministic gathers:
/// the springs of particle i are entries [offsets[i], offsets[i+1]).
struct ParticleSpringIncidence {
  std::vector<int> offsets;            ///< #P+1
  std::vector<int> springs;            ///< #incidences, spring ids, ascending within a row
  std::vector<std::int8_t> first_end;  ///< #incidences, 1 if the particle is springs(s,0), else 0
};

/// Compressed rows of the spring -> coupling and particle -> coupling incidences, for
/// deterministic gathers: the couplings of spring s are spring_couplings[spring_offsets[s],
/// spring_offsets[s+1]), those touching particle p (an end of either of their springs)
/// particle_couplings[particle_offsets[p], particle_offsets[p+1]); ascending within a row.
struct SpringCouplingIncidence {
  std::vector<int> spring_offsets;      ///< #S+1
  std::vector<int> spring_couplings;    ///< 2#C
  std::vector<int> particle_offsets;    ///< #P+1
  std::vector<int> particle_couplings;  ///< one entry per distinct particle of each coupling
};

/// Particles, springs and surface triangles of one cloth, ready to be stepped.
struct SpringModel {
  Eigen::VectorXd mass;              ///< #P lumped particle masses (kg)
  Eigen::VectorXd inverse_mass;      ///< #P 1/mass, 0 for pinned particles (1/kg)
  std::vector<std::uint8_t> pinned;  ///< #P 1 if the particle's motion is prescribed
  Eigen::MatrixX2i springs;          ///< #S x 2 particle ids (i, j)
  Eigen::VectorXd rest_length;       ///< #S rest lengths l0 (m)
  Eigen::VectorXd stiffness;         ///< #S stiffnesses k (N/m)
  Eigen::VectorXd damping;           ///< #S viscous coefficients nu (N s/m)
  std::vector<SpringKind> kind;      ///< #S
  /// Pairs of springs whose stretches are coupled, with energy
  /// Gamma_c (|x_a| - l0_a)(|x_b| - l0_b) for springs a, b = couplings.row(c): the angular terms
  /// of Delingette 2008's triangular springs (topology/membrane_stiffness.hpp). Often empty.
  Eigen::MatrixX2i couplings;                  ///< #C x 2 spring ids (a, b), a != b
  Eigen::VectorXd coupling_stiffness;          ///< #C Gamma (N/m), of either sign
  SpringCouplingIncidence coupling_incidence;  ///< filled by finalize_model()
  Eigen::MatrixX3i triangles;         ///< #T x 3 particle ids of the surface, quads split in two,
                                      ///< counter-clockwise seen from the front; for aerodynamics
  ParticleSpringIncidence incidence;  ///< filled by finalize_model()
  Eigen::MatrixX2i surface_edges;     ///< #E x 2 edges of the triangles, (i < j), each once,
                                      ///< sorted; filled by finalize_model(), for collisions
  /// 3#P material (rest) coordinates of the particles (m), xyz interleaved, as compiled from the
  /// complex; for self-collision, which ignores pairs that are neighbours in the material (the
  /// two lips of a cut share their material points). Empty when unknown (hand-built models).
  Eigen::VectorXd rest_x;
  /// What this model is, for the caches derived from it (geometry-central's modificationTick):
  /// a process-wide generation counter that finalize_model() advances and nothing else sets, so
  /// two finalizations never share a value and 0 means "never finalized". Every cache a workspace
  /// keeps (Projective Dynamics system and factorisation, matrix pattern, collision pairs, warm
  /// starts) is keyed on it: after changing any field, call finalize_model() again. A copy keeps
  /// the identity, which is right while the copy is not changed.
  std::uint64_t identity = 0;

  int particle_count() const { return static_cast<int>(mass.size()); }
  int spring_count() const { return static_cast<int>(springs.rows()); }
};

/// Fills the derived fields (inverse_mass, incidence, coupling_incidence, surface_edges) from the
/// others and gives the model a new identity. Call after filling or changing a model.
void finalize_model(SpringModel& model);

/// Dynamic state: positions and velocities of every particle, xyz interleaved.
struct State {
  Eigen::VectorXd x;  ///< 3#P positions (m)
  Eigen::VectorXd v;  ///< 3#P velocities (m/s)
  double time = 0.0;  ///< simulated time (s)
};

}  // namespace tissu
