#pragma once
/// \file
/// Energies of the mass-spring system, for statistics and tests.

#include "solver/solver_params.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Sum over particles of 1/2 m |v|^2 (J).
double kinetic_energy(const SpringModel& model, const State& state);

/// Elastic energy sum over springs of 1/2 k (|xi - xj| - l0)^2 plus gravitational energy
/// sum of -m g . x (J), relative to the origin.
double potential_energy(const SpringModel& model, const Eigen::Vector3d& gravity,
                        const State& state);

/// Total mass sum of m_i (kg), compensated (solver/compensated_sum.hpp).
double total_mass(const SpringModel& model);

}  // namespace tissu
