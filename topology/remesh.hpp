#pragma once
/// \file
/// Anisotropic remeshing of a triangle cloth after ARCSim (Narain, Samii & O'Brien 2012,
/// "Adaptive anisotropic remeshing for cloth simulation", section 5): edges longer than the
/// sizing metric wants are split, edges are flipped towards the metric's Delaunay triangulation,
/// and particles made by refinement are collapsed away where the metric lets the cells grow back.
/// Unlike bisection (refine.hpp, coarsen.hpp), the cells may be long along a fold and short
/// across it.

#include "topology/cloth_complex.hpp"
#include "topology/refinement_options.hpp"
#include "topology/sizing_field.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

/// What one remeshing pass did.
struct RemeshReport {
  int splits = 0;     ///< edges split at their rest midpoint
  int flips = 0;      ///< edges flipped
  int collapses = 0;  ///< particles removed
};

/// The squared length of the edge of `dart` in the sizing metric: the mean of e^T M_v e at its two
/// ends, M_v the rest-area-weighted mean of FaceRest::sizing_metric_per_m2 over the faces around
/// v (ARCSim's vertex sizing).
double edge_metric_length2(const ClothComplex& lcc, Dart_const_handle dart);

/// Whether the edge of `dart`, (a, b) between the triangles (a, b, c) and (b, a, e), should be
/// flipped to (c, e): the anisotropic Delaunay test of Bossen & Heckbert 1996 in the mean metric
/// M of the four corners, with w = c and y = e,
///   wedge(b - e, a - e) <a - c, M (b - c)> + <b - e, M (a - e)> wedge(a - c, b - c)
///     < -0.1 (wedge(b - e, a - e) + wedge(a - c, b - c)),
/// wedge(p, q) = (p x q) . n in material coordinates, n the unit normal of (a, b, c): the
/// M-angles at c and e add up to more than pi, with a margin (ARCSim's is 0.01; 0.1 here, which
/// flips less for the same shapes) so that no edge flips back and forth. Where M asks nothing of
/// the edge (its trace under 1 / (9 |a - b|^2), a target over three times the edge in every
/// direction), the test is the Euclidean Delaunay one, with M = I / |a - b|^2: flat cloth keeps
/// well-shaped triangles. False on the border.
bool should_flip(const ClothComplex& lcc, Dart_const_handle dart);

/// One pass over the cloth, which must be made of triangles, following the sizing metric of
/// `options` (compute_sizing_metric(), sizing_metric.hpp):
/// 1. every edge whose metric length exceeds 1 and whose rest length is at least twice
///    options.min_edge_length_m is split, the longest first, until none is left or the cloth has
///    options.max_particles particles; the edges around each new particle are flipped where
///    should_flip() says so;
/// 2. every edge is flipped where should_flip() says so and flip_refusal() allows, in rounds,
///    until a round flips nothing (at most 8 rounds);
/// 3. when `hysteresis` is positive, every particle made by refinement that collapse_refusal()
///    allows to collapse onto a neighbour, leaving every new edge at that neighbour shorter than
///    `hysteresis` in the metric and no new triangle of quality (lowest_quality()) under
///    1 / options.max_aspect_ratio, for options.coarsen_after_passes passes in a row, is
///    collapsed onto the neighbour whose new edges are shortest; the edges around it are then
///    flipped where should_flip() says so.
/// Every edit keeps the rest area, the masses and the free particles' momentum (split_edge.hpp,
/// flip_edge.hpp, collapse_vertex.hpp).
RemeshReport remesh(ClothComplex& lcc, const RefinementOptions& options, double hysteresis,
                    const SpringSettings& settings, const SizingInputs& inputs = {});

}  // namespace tissu
