#include "solver/forces/force_jacobian.hpp"

#include "solver/forces/spring_coupling.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/parallel.hpp"

namespace tissu {

void force_position_jacobian(const SpringModel& model, const Eigen::VectorXd& x,
                             const ForceJacobianOptions& options, ForceJacobianWorkspace& workspace,
                             Eigen::SparseMatrix<double>& dfdx) {
  const int springs = model.spring_count();
  update_spring_block_pattern(model, workspace.pattern);
  workspace.spring_blocks.resize(springs);
  const bool clamp = options.clamp_compressed_springs;
  const bool coupled = model.couplings.rows() > 0;
  if (coupled) {
    spring_coupling_tensions(model, x, workspace.spring_stretch, workspace.coupling_tension);
  }

#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    const auto xi = x.segment<3>(3 * model.springs(s, 0));
    const auto xj = x.segment<3>(3 * model.springs(s, 1));
    const double k = model.stiffness[s];
    const double l0 = model.rest_length[s];
    workspace.spring_blocks[s] =
        clamp ? spring_force_jacobian_clamped(xi, xj, k, l0) : spring_force_jacobian(xi, xj, k, l0);
    if (coupled) {
      workspace.spring_blocks[s] +=
          coupling_tension_jacobian(xi, xj, workspace.coupling_tension[s], clamp);
    }
  }

  workspace.diagonal.setZero(model.particle_count());
  assemble_spring_block_matrix(model, workspace.pattern, workspace.spring_blocks,
                               workspace.diagonal, false, dfdx);
  if (coupled) add_coupling_jacobian_blocks(model, workspace.pattern, x, 1.0, false, dfdx);
}

void force_velocity_jacobian(const SpringModel& model, const Environment& environment,
                             const Eigen::VectorXd& x, ForceJacobianWorkspace& workspace,
                             Eigen::SparseMatrix<double>& dfdv) {
  const int springs = model.spring_count();
  update_spring_block_pattern(model, workspace.pattern);
  workspace.spring_blocks.resize(springs);

#pragma omp parallel for schedule(static) if (springs >= min_parallel_items)
  for (int s = 0; s < springs; ++s) {
    workspace.spring_blocks[s] =
        spring_damping_force_jacobian(x.segment<3>(3 * model.springs(s, 0)),
                                      x.segment<3>(3 * model.springs(s, 1)), model.damping[s]);
  }

  workspace.diagonal = -environment.air_damping * model.mass;
  assemble_spring_block_matrix(model, workspace.pattern, workspace.spring_blocks,
                               workspace.diagonal, false, dfdv);
}

}  // namespace tissu
