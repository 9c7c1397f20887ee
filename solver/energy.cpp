#include "solver/energy.hpp"

#include "solver/compensated_sum.hpp"
#include "solver/forces/spring_coupling.hpp"
#include "solver/forces/spring_force.hpp"

namespace tissu {

// serial sums: energies are statistics, and a fixed summation order keeps them reproducible

double kinetic_energy(const SpringModel& model, const State& state) {
  double energy = 0.0;
  for (int p = 0; p < model.particle_count(); ++p) {
    energy += 0.5 * model.mass[p] * state.v.segment<3>(3 * p).squaredNorm();
  }
  return energy;
}

double potential_energy(const SpringModel& model, const Eigen::Vector3d& gravity,
                        const State& state) {
  double energy = 0.0;
  for (int s = 0; s < model.spring_count(); ++s) {
    energy += spring_energy(state.x.segment<3>(3 * model.springs(s, 0)),
                            state.x.segment<3>(3 * model.springs(s, 1)), model.stiffness[s],
                            model.rest_length[s]);
  }
  energy += spring_coupling_energy(model, state.x);
  for (int p = 0; p < model.particle_count(); ++p) {
    energy -= model.mass[p] * gravity.dot(state.x.segment<3>(3 * p));
  }
  return energy;
}

double total_mass(const SpringModel& model) {
  CompensatedSum total_kg;
  for (const double m : model.mass) total_kg.add(m);
  return total_kg.value();
}

}  // namespace tissu
