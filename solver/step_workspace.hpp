#pragma once
/// \file
/// Scratch buffers of a time step, owned by the caller (like MuJoCo's mjData) so that stepping
/// allocates nothing once the sizes are known. Caches are keyed on the model's identity
/// (SpringModel::identity), never on sizes. Not shared between threads stepping concurrently.

#include <Eigen/Core>
#include <cstdint>

#include "solver/collision/obstacle_distance_cache.hpp"
#include "solver/collision/self_collision.hpp"
#include "solver/forces/accumulate_forces.hpp"
#include "solver/integrators/implicit_euler_workspace.hpp"
#include "solver/integrators/newton_workspace.hpp"
#include "solver/integrators/projective_dynamics_workspace.hpp"
#include "solver/integrators/quasi_newton_workspace.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

struct StepWorkspace {
  ForceWorkspace forces;              ///< buffers of accumulate_forces()
  Eigen::VectorXd force;              ///< 3#P total force of the last evaluation (N)
  ImplicitEulerWorkspace implicit;    ///< buffers of implicit_euler_step()
  ProjectiveDynamicsWorkspace pd;     ///< buffers and caches of projective_dynamics_step()
  NewtonWorkspace newton;             ///< buffers and caches of newton_step()
  QuasiNewtonWorkspace quasi_newton;  ///< buffers and caches of quasi_newton_step()
  Eigen::VectorXd step_start_x;  ///< 3#P positions before the step, when there are obstacles (m)
  int obstacle_contacts = 0;     ///< particle-obstacle contacts resolved by the last step
  int strain_limited = 0;        ///< structural springs the last step's strain limit shortened
  /// #obstacles x #P normal impulse per unit mass of the minimiser's contact penalties in the last
  /// step (m/s), on the model of identity `obstacle_penalty_impulse_model`: the next step's
  /// friction lags its normal force from it (contact_planes.hpp)
  Eigen::MatrixXd obstacle_penalty_impulse;
  std::uint64_t obstacle_penalty_impulse_model = 0;
  /// with SolverParams::friction_in_step, the same without the planes that slid with friction in
  /// the step: what friction after it may use
  Eigen::MatrixXd obstacle_impulse_after_step;
  /// 3 x #P outward normal of the obstacle that held each particle in the last step, 0 if none
  Eigen::Matrix3Xd obstacle_holding_normal;
  /// each particle's last distance query to each mesh obstacle, to skip those that cannot matter
  ObstacleDistanceCache obstacle_distances;
  SelfCollisionReport self_collision;        ///< what self-collision handling did in the last step
  SelfCollisionCache self_collision_pairs;   ///< broad-phase pairs kept between steps
  Eigen::VectorXd before_self_collision_x;   ///< 3#P, when there are obstacles too (m)
  std::vector<int> moved_by_self_collision;  ///< particles it moved, checked against obstacles
};

/// The last step's obstacle_penalty_impulse, if that step was of `model` (its identity; not after
/// a remesh or a tear, which renumber the particles), else nullptr.
inline const Eigen::MatrixXd* lagged_penalty_impulse(const SpringModel& model,
                                                     const StepWorkspace& workspace) {
  const bool same_model = workspace.obstacle_penalty_impulse_model == model.identity &&
                          workspace.obstacle_penalty_impulse.cols() == model.particle_count();
  return same_model ? &workspace.obstacle_penalty_impulse : nullptr;
}

}  // namespace tissu
