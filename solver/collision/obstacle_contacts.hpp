#pragma once
/// \file
/// Keeps the cloth outside the obstacles after each step, with Coulomb friction. CGAL-free.

#include <vector>

#include "solver/collision/obstacle.hpp"
#include "solver/collision/obstacle_distance_cache.hpp"
#include "solver/spring_model.hpp"

namespace tissu {

/// Projects every free particle that ended step h within an obstacle's thickness back out to it,
/// after the integrator, whichever it is (a velocity-level impulse response as in Bridson, Fedkiw
/// & Anderson 2002, section 7.2, applied to particles against rigid obstacles):
/// - position: moved along the outward normal n to distance thickness; this adds no velocity,
///   so resolving a contact never adds energy;
/// - velocity relative to the obstacle, v_r = v - v_obstacle: an approaching normal part
///   v_n = v_r . n < 0 is removed (inelastic contact), an impulse dv_n = -v_n per unit mass, or
///   d / h if the particle was pushed out by d and that is more (a squeezed particle);
/// - friction on the tangential part v_t (Coulomb): it stops if |v_t| <= mu_s dv_n (static),
///   else loses mu_k dv_n of its length, down to zero (kinetic); the position then moves by h times
///   the change of v_t, so that x_{n+1} - x_n = h v_{n+1} holds along the surface as it does in the
///   integrator. A particle on a slope of angle a then sticks when tan a <= mu_s and otherwise
///   accelerates at g (sin a - mu_k cos a), as Coulomb's law says.
/// The obstacle's velocity there is its surface's: rigid motion, plus an animated mesh's
/// deformation (the mean velocity over the step of the nearest point of its triangle).
/// A particle whose step ends clear of an obstacle, or near its far side, but whose path went
/// into it (a thin obstacle, a fast particle, or a fast obstacle: the path is measured relative to
/// the obstacle's surface, from where `start_x` would be had it moved with that surface) is stopped
/// where the path first touches it, or, if it started touching, kept on the side it started from:
/// no tunnelling. A path that ends clear and only grazed the thickness is left alone. Obstacles
/// are resolved one after the other, at their place at `time_s` (the end of the step), their
/// surface at the start of the step serving only to carry the path's start.
/// A particle that the last of them leaves inside another deeper than its thickness (a crease
/// where two overlap) goes back to its start, carried by that obstacle's surface, at its velocity.
/// Pinned particles are left alone. Sets column p of `holding_normal` (3 x #P, resized) to the
/// outward unit normal of the obstacle that held particle p (the last one, if several did), zero
/// where none did, and returns the number of contacts.
/// `step_normal_impulse` (#obstacles x #P, m/s, or empty) is the normal impulse per unit mass each
/// obstacle already gave each particle during the step (a minimiser's contact penalty,
/// contact_planes.hpp): friction is then bounded by mu times it plus dv_n. `distances`, if given
/// (prepared for this step), skips a mesh's queries where it knows the particle farther than
/// that, and records the others.
int resolve_obstacle_contacts(const SpringModel& model, const std::vector<Obstacle>& obstacles,
                              double time_step_s, double time_s, const Eigen::VectorXd& start_x,
                              State& state, Eigen::Matrix3Xd& holding_normal,
                              const Eigen::MatrixXd& step_normal_impulse = Eigen::MatrixXd(),
                              ObstacleDistanceCache* distances = nullptr);

/// The same for those of the particles `moved` (indices, none pinned) that another response
/// (self-collision) has moved inside an obstacle, beyond its surface: obstacles have the last word,
/// as a cloth layer pushed by another cannot enter a body. One pushed only within an obstacle's
/// thickness is left there: pushing it out again would move it through the layer that pushed it
/// (two layers pressed on a floor). Each path is again measured from `start_x`, the step's start.
void resolve_obstacle_contacts_of(const std::vector<int>& moved,
                                  const std::vector<Obstacle>& obstacles, double time_step_s,
                                  double time_s, const Eigen::VectorXd& start_x, State& state,
                                  ObstacleDistanceCache* distances = nullptr);

}  // namespace tissu
