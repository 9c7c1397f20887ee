#pragma once
/// \file
/// Obstacle contacts inside a step's minimisation: each particle near an obstacle at the start of
/// the step is held by the obstacle's offset surface there, linearised to a plane, through a
/// one-sided quadratic penalty added to backward Euler's incremental potential (the penalty
/// contacts of Baraff & Witkin 1998 and Martin et al. 2011 taken into the potential, as IPC, Li et
/// al. 2020, takes its barrier), and by Coulomb friction in the potential too, its normal force
/// lagged (IPC's lagged friction, Li et al. 2020, section 5). The contact
/// projection after the step (obstacle_contacts.hpp) stays, and applies Coulomb friction with the
/// normal impulse the penalty gave where no friction acted in the step. CGAL-free.

#include <Eigen/Core>
#include <vector>

#include "solver/collision/obstacle.hpp"
#include "solver/collision/obstacle_distance_cache.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Below this tangential speed, friction in the step grows smoothly from zero to its bound (IPC's
/// epsilon_v, Li et al. 2020): held cloth creeps at most this fast (m/s).
constexpr double friction_slip_speed_m_per_s = 1e-3;

/// One particle near one obstacle, the obstacle's surface offset by its thickness linearised near
/// the particle (find_contact_planes()): the particle may not go below the plane through `point`
/// with normal `normal`. Penalty energy 1/2 k max(0, (point - x) . normal)^2 (J). Friction energy
/// F f0(|u|) (J), u = P (x - start) the particle's slip along the plane over the step (P = I - n
/// n^T), F = mu_k lambda its bound (N), and f0 IPC's smoothed |u|: f0(y) = -y^3 / (3 e^2) + y^2 / e
/// + e / 3 below e = friction_slip_speed_m_per_s h, y above, so that the friction force F f0'(|u|)
/// grows from 0 at rest to F at a slip of e and stays F beyond.
struct ContactPlane {
  int particle = 0;
  int obstacle = 0;                                 ///< index in SolverParams::obstacles
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< on the offset surface at the step's end (m)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, outwards
  double stiffness_n_per_m = 0.0;                     ///< k = beta m / h^2 (N/m)
  /// the particle's start, carried by the obstacle's surface over the step (m): where it would be
  /// with no slip
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  double friction_n = 0.0;    ///< F = mu_k lambda, lambda the normal force lagged (N); 0: none
  double slip_scale_m = 0.0;  ///< e = friction_slip_speed_m_per_s h (m)
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

/// Gives each plane its friction bound F = mu_k lambda (the obstacle's kinetic_friction) and its
/// slip scale e, lambda the normal force (N) lagged as IPC's friction lags it (Li et al. 2020,
/// section 5):
/// - from the last step's normal impulses per unit mass `lagged_impulse` (#obstacles x #P, m/s,
///   contact_normal_impulses() of that step, on the same model): lambda = m J / h, the contact
///   force the last converged step found;
/// - without them (nullptr: the first step, or a remesh or a tear renumbered the particles),
///   estimated at the step's first iterate x_0 (3#P, m) from the potential's gradient there
///   without the contacts (3#P, N): one gradient step of the particle alone takes it to
///   x_0 - (h^2 / m) g, and lambda = (m / h^2) times that point's depth below the plane, or 0. A
///   particle resting on a floor gets its weight plus what its springs press down, one its springs
///   lift off none. Not used when the lag is there: used in its place, the skirt caught on a
///   walking leg and stayed stretched (skirt_walk, docs/benchmarks.md); the springs' forces at
///   x_0 = x_n + h v_n are those of an extrapolated shape, not the contact's.
void lag_contact_friction(const SpringModel& model, const std::vector<Obstacle>& obstacles,
                          const Eigen::MatrixXd* lagged_impulse,
                          const Eigen::VectorXd& first_iterate,
                          const Eigen::VectorXd& gradient_without_contacts, double time_step_s,
                          std::vector<ContactPlane>& planes);

/// A plane whose particle slipped more than this many slip scales e over the step slid, its
/// friction at its bound: 10 e is a slip of 1 cm/s.
constexpr double sliding_slip_ratio = 10.0;

/// Zeroes the entries of `impulse_m_per_s` (#obstacles x #P) whose plane's particle slid in the
/// step to x (3#P, m) with friction in it: that friction has acted at its bound, the friction
/// after the step must not apply it again (and, by the velocity alone, hold a particle its
/// springs pull harder than friction can). Slower particles keep it: friction after the step then
/// holds them exactly, as it holds a particle on a slope that friction in the step, with its
/// smoothed start and its lagged normal force, lets creep.
void remove_friction_given_in_step(const std::vector<ContactPlane>& planes,
                                   const Eigen::VectorXd& x, Eigen::MatrixXd& impulse_m_per_s);

/// How far x (3, m) is below the plane (m), 0 when above it.
inline double contact_depth_m(const ContactPlane& plane, const Eigen::Vector3d& x) {
  const double depth_m = (plane.point - x).dot(plane.normal);
  return depth_m > 0.0 ? depth_m : 0.0;
}

/// The plane's slip u = P (x - start) along it over the step (3, m).
inline Eigen::Vector3d contact_slip_m(const ContactPlane& plane, const Eigen::Vector3d& x) {
  const Eigen::Vector3d moved = x - plane.start;
  return moved - moved.dot(plane.normal) * plane.normal;
}

/// The planes' penalty and friction energy at x (3#P, m) (J); with a gradient, adds their
/// gradient to it (3#P, N): -k depth n, and F f0'(|u|) u / |u|. Summed in the planes' order:
/// deterministic.
double add_contact_potential(const std::vector<ContactPlane>& planes, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient);

/// The normal impulse per unit mass each plane's penalty gave over a step of h ending at x
/// (3#P, m): h k depth / m = beta depth / h (m/s), as a #obstacles x #P matrix (zero elsewhere),
/// for the friction after the step.
void contact_normal_impulses(const SpringModel& model, const std::vector<ContactPlane>& planes,
                             int obstacle_count, double time_step_s, const Eigen::VectorXd& x,
                             Eigen::MatrixXd& impulse_m_per_s);

}  // namespace tissu
