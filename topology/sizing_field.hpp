#pragma once
/// \file
/// The sizing field that drives adaptive refinement and coarsening: per face, the edge length the
/// cloth wants there, measured in rest space (after ARCSim, Narain, Samii & O'Brien 2012,
/// "Adaptive anisotropic remeshing for cloth simulation", section 4; isotropic here).

#include <vector>

#include "solver/collision/obstacle.hpp"
#include "topology/cloth_complex.hpp"
#include "topology/refinement_options.hpp"

namespace tissu {

/// What the sizing field reads besides the complex.
struct SizingInputs {
  const std::vector<Obstacle>* obstacles = nullptr;  ///< none when null
  double time_s = 0.0;                               ///< where moving obstacles are
};

/// Sets FaceRest::sizing_per_m2 = 1 / L^2 on every face, L the target edge length in rest space
/// (m), as the sum of the terms of `options` (each 1 / L_term^2, as ARCSim sums its metrics). Per
/// edge of the face, the largest over them:
/// - curvature relative to rest, (kappa_e / curvature_threshold_rad)^2 with
///   kappa_e = |theta_e - theta0_e| / delta0_e (theta the signed dihedral angle now, theta0 at
///   rest, delta0 the rest distance between the two faces' centroids): a rest shape that is
///   curved is not refined while the cloth keeps it;
/// - velocity: kappa_e also at the positions x + lookahead_s v, the larger kept;
/// - strain: (|eps_e| / strain_threshold)^2 / L_f^2, eps_e the edge's strain and L_f the face's
///   longest rest edge: the face is split while an edge is strained past the threshold;
/// and per face:
/// - obstacles: |grad h|^2 / (16 h^2) averaged over the face's corners, h the height of the
///   face's corners above the tangent plane of the obstacle nearest each corner (at least the
///   obstacle's thickness), grad in rest space: zero for cloth lying flat on a floor; on a curved
///   obstacle, faces whose chords sag by about the thickness (ARCSim's metric / 16);
/// then at least 1 / max_edge_length_m^2 when a maximum is set. Also sets FaceRest::sizing_term:
/// the term with the largest share (an edge term's largest over the face's edges; for velocity,
/// what looking ahead adds to the curvature term), or none where the face's parent (longest edge
/// sqrt(2) L) would be under half the target (2 L^2 sizing < 1/4): coarsening at the default
/// hysteresis may merge it back.
void compute_sizing(ClothComplex& lcc, const RefinementOptions& options,
                    const SizingInputs& inputs);

/// The face's longest rest edge in the sizing metric, squared: L^2 FaceRest::sizing_per_m2. Above
/// 1 the face is coarser than the field wants; refinement bisects that edge.
double face_metric_length2(const ClothComplex& lcc, Dart_const_handle dart);

}  // namespace tissu
