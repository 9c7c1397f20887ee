#pragma once
/// \file
/// The anisotropic sizing metric that remesh.hpp follows: per face, a tensor in material
/// coordinates that wants cells short across a fold and long along it (Narain, Samii & O'Brien
/// 2012, "Adaptive anisotropic remeshing for cloth simulation", section 4).

#include <Eigen/Core>

#include "topology/cloth_complex.hpp"
#include "topology/refinement_options.hpp"
#include "topology/sizing_field.hpp"

namespace tissu {

/// Sets FaceRest::sizing_metric_per_m2 on every triangle, the sum of the terms of `options`
/// (each a symmetric tensor in the face's rest plane, 1/m^2), as ARCSim sums its metrics:
/// - curvature relative to rest: S^2 / curvature_threshold_rad^2, with the face's shape operator
///   relative to its rest shape S = 1 / (2 A) sum_e (theta_e - theta0_e) |e| t_e t_e^T over its
///   interior edges (ARCSim's curvature(), Grinspun et al. 2006's discrete shape operator): A the
///   face's rest area, |e| an edge's rest length, t_e the unit rest-plane vector across it, theta
///   and theta0 its signed dihedral angle now and at rest. A fold along one edge wants edges
///   across it short and along it free; a rest shape that is curved is not refined while the
///   cloth keeps it;
/// - velocity: the same at x + lookahead_s v, where its trace is the larger;
/// - strain: (|eps| / strain_threshold)^2 / L_f^2 in every direction of the face, eps the
///   largest engineering strain of its edges and L_f its longest rest edge;
/// - obstacles: obstacle_metric() (sizing_geometry.hpp);
/// - at least 1 / max_edge_length_m^2 in every direction when a maximum is set;
/// then its eigenvalues in the face's plane are clamped to at most 1 / min_edge_length_m^2 and
/// at least the largest over max_aspect_ratio^2. Also sets FaceRest::sizing_per_m2 to the largest
/// eigenvalue and FaceRest::sizing_term to the term with the largest trace (none where the face
/// is under half the target along every edge).
void compute_sizing_metric(ClothComplex& lcc, const RefinementOptions& options,
                           const SizingInputs& inputs);

/// e^T M e for the rest edge e from `a_m` to `b_m`: its squared length in the metric M; above 1
/// the edge is longer than the cloth wants.
double metric_length2(const Eigen::Matrix3d& metric_per_m2, const Point3& a_m, const Point3& b_m);

}  // namespace tissu
