#pragma once
/// \file
/// Obstacle contacts inside a step's minimisation: each particle near an obstacle at the start of
/// the step is held by the obstacle's offset surface there, linearised to a plane, through a
/// one-sided quadratic penalty added to backward Euler's incremental potential (the penalty
/// contacts of Baraff & Witkin 1998 and Martin et al. 2011 taken into the potential, as IPC, Li et
/// al. 2020, takes its barrier). The contact projection after the step (obstacle_contacts.hpp)
/// stays, and applies Coulomb friction with the normal impulse the penalty gave. CGAL-free.

#include <Eigen/Core>
#include <vector>

#include "solver/collision/obstacle.hpp"
#include "solver/collision/obstacle_distance_cache.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// One particle near one obstacle, the obstacle's surface offset by its thickness linearised near
/// the particle (find_contact_planes()): the particle may not go below the plane through `point`
/// with normal `normal`. Penalty energy 1/2 k max(0, (point - x) . normal)^2 (J).
struct ContactPlane {
  int particle = 0;
  int obstacle = 0;                                 ///< index in SolverParams::obstacles
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< on the offset surface at the step's end (m)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, outwards
  double stiffness_n_per_m = 0.0;                     ///< k = beta m / h^2 (N/m)
};

/// The planes of the free particles within reach of an obstacle where it is at the step's end
/// `end_time_s`: whose first iterate x_0 = x_n + h v_n (3#P, m) is closer to it than its thickness
/// plus how far the particle moves in the step (|x_0 - x_n|, from its start x_n, 3#P, m) plus the
/// thickness again, so that a particle arriving during the step is caught. Each plane is the
/// tangent plane of the offset surface at x_0's nearest point; none where that plane would put
/// the start (carried by the obstacle's surface over the step, carry_with_surface()) more than the
/// thickness below it (x_0 gone round a curved obstacle or past its middle: no plane holds the
/// path, and the projection after the step keeps the particle out). `stiffness` is beta
/// (dimensionless): k = beta m / h^2, so that a particle resting on a plane under gravity sinks
/// g h^2 / beta into it. In particle order, then obstacle order. `distances`, if given (prepared
/// for this step), skips a mesh's queries where it knows x_0 farther than that, and records the
/// others.
void find_contact_planes(const SpringModel& model, const std::vector<Obstacle>& obstacles,
                         double stiffness, double time_step_s, double end_time_s,
                         const Eigen::VectorXd& start_x, const Eigen::VectorXd& first_iterate,
                         std::vector<ContactPlane>& planes,
                         ObstacleDistanceCache* distances = nullptr);

/// How far x (3, m) is below the plane (m), 0 when above it.
inline double contact_depth_m(const ContactPlane& plane, const Eigen::Vector3d& x) {
  const double depth_m = (plane.point - x).dot(plane.normal);
  return depth_m > 0.0 ? depth_m : 0.0;
}

/// The planes' penalty energy at x (3#P, m) (J); with a gradient, adds the penalty's gradient
/// -k depth n to it (3#P, N). Summed in the planes' order: deterministic.
double add_contact_potential(const std::vector<ContactPlane>& planes, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient);

/// The normal impulse per unit mass each plane's penalty gave over a step of h ending at x
/// (3#P, m): h k depth / m = beta depth / h (m/s), as a #obstacles x #P matrix (zero elsewhere),
/// for the friction after the step.
void contact_normal_impulses(const SpringModel& model, const std::vector<ContactPlane>& planes,
                             int obstacle_count, double time_step_s, const Eigen::VectorXd& x,
                             Eigen::MatrixXd& impulse_m_per_s);

}  // namespace tissu
