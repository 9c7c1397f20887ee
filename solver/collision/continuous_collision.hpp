#pragma once
/// \file
/// Proximity and continuous collision tests for a vertex-triangle or edge-edge pair whose four
/// particles move linearly during a step. CGAL-free.

#include <optional>

#include "solver/collision/contact_pair.hpp"

namespace tissu {

/// Positions of the four particles at the start of the step and their displacements over it (m).
struct PairMotion {
  std::array<Eigen::Vector3d, 4> start;
  std::array<Eigen::Vector3d, 4> displacement;

  Eigen::Vector3d at(int k, double t) const { return start[k] + t * displacement[k]; }
};

/// The pair at the end of the step: the distance between its primitives, and their closest points
/// if they are closer than the thickness, with the normal oriented by the side the pair started on.
struct EndProximity {
  double distance_m = 0.0;
  std::optional<ContactPair> contact;
};

/// The pair at the end of the step, against a thickness `thickness_m`.
EndProximity proximity_at_end(const CandidatePair& pair, const PairMotion& motion,
                              double thickness_m);

/// True when c3 t^3 + c2 t^2 + c1 t + c0 cannot vanish on [0, 1]: its Bernstein coefficients there
/// (c0, c0 + c1/3, c0 + 2 c1/3 + c2/3, c0 + c1 + c2 + c3) all have one sign, clear of round-off,
/// and the cubic is a convex combination of them (the non-penetration filter of Tang, Manocha &
/// Tong 2010, "Fast continuous collision detection using deforming non-penetration filters").
bool cubic_keeps_its_sign_on_unit_interval(double c3, double c2, double c1, double c0);

/// True when the pair's primitives stay farther apart than `distance_m` all step. Any two of
/// their points close in by a convex combination of the relative displacements of their corners,
/// so the distance at time t is at least the distance at the end less (1 - t) times the largest
/// of those (the bound of conservative advancement, Mirtich 1996). A flat sheet's
/// neighbours are coplanar all step, so the coplanarity cubic cannot rule them out; this can.
bool stays_farther_than(const CandidatePair& pair, const PairMotion& motion, double distance_m);

/// The same test from a lower bound `end_distance_at_least_m` on the distance at the end of the
/// step (m), known without computing the closest points.
bool stays_farther_than(const CandidatePair& pair, const PairMotion& motion, double distance_m,
                        double end_distance_at_least_m);

/// The first time in [0, 1] at which the four points are coplanar with the closest points of the
/// pair within `tolerance_m` of each other (the pair touches), found from the roots of the cubic
/// (x1 - x0) x (x2 - x0) . (x3 - x0) = 0 in t (Provot 1997; Bridson, Fedkiw & Anderson 2002).
/// The contact's normal is that of the triangle, or of the two edges, at that time. Pairs that
/// touch without closing in along it (sliding, or moving apart) are not impacts.
std::optional<ContactPair> first_impact(const CandidatePair& pair, const PairMotion& motion,
                                        double tolerance_m);

}  // namespace tissu
