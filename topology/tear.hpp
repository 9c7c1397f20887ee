#pragma once
/// \file
/// Tearing: the cloth complex comes apart along edges where it is overstretched, or where a
/// scripted knife cuts it.

#include <vector>

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"
#include "topology/tearing_options.hpp"

namespace tissu {

/// Unsews the two faces of the dart's edge (unsew<2>). Where that breaks a vertex's fan of faces in
/// two, CGAL gives the second fan a copy of the vertex attribute: each copy keeps the position and
/// velocity and gets the mass of its own faces (density x rest area / corners), so the total mass
/// and the linear momentum are unchanged. The bending spring across the edge goes with the shared
/// edge; no other spring joins the two faces, so none is left across the tear. Both sides keep
/// their structural spring, as a cloth cut that way from the start would. Marks the edge's ends
/// Particle::on_crack. Throws std::invalid_argument on a boundary edge.
TearReport tear_edge(ClothComplex& lcc, Dart_handle dart, const SpringSettings& settings);

/// One tearing pass. The interior and border edges whose strain l / l0 - 1 exceeds the tearing
/// strain at their midpoint (TearingOptions::strain_threshold times the lowest factor of the weak
/// regions holding it) are taken by decreasing strain over tearing strain (container order on
/// ties, so the pass is deterministic), skipping those with an end already touched by this pass.
/// Each breaks at one end: one whose fan is open (the border or a crack tip, so cracks grow from
/// their tips), else one already on a crack. The end fractures as in ARCSim (Pfaff et al. 2014,
/// "Adaptive tearing and cracking of thin sheets", section 4): the crack runs perpendicular to the
/// direction of largest stretch there, the top eigenvector of the area-weighted mean right
/// Cauchy-Green tensor C = F^T F of its corner triangles. It tears the edge most perpendicular to
/// that direction; a vertex inside the cloth (whose fan is closed) also tears the best edge on the
/// other side, so that it splits. An edge whose tear would cut off a piece of fewer than
/// min_piece_faces faces is never chosen (no loose triangles or shreds). At most max_tears_per_step
/// edges are torn: the solver relaxes the cloth between passes, which moves the largest strain to
/// the crack's tip. Crack tips (the far ends of torn edges) are then refined when
/// tip_min_edge_length_m > 0, up to `max_particles` (triangle cloths only, as for refine()).
TearReport tear(ClothComplex& lcc, const TearingOptions& options, int max_particles,
                const SpringSettings& settings);

/// Cuts the cloth along a polyline in material coordinates: from the vertex nearest its first
/// point, walks from vertex to vertex along interior edges, each step to the neighbour that best
/// follows the polyline (closest to it, moving forward along it), and tears every edge walked.
/// The path follows mesh edges, so it matches the polyline to within about one edge length.
TearReport cut_along(ClothComplex& lcc, const std::vector<Eigen::Vector3d>& polyline_m,
                     const SpringSettings& settings);

/// The connected pieces of cloth.
int count_pieces(const ClothComplex& lcc);

/// Edges with a face on one side only: the cloth's border, tears included.
int count_boundary_edges(const ClothComplex& lcc);

}  // namespace tissu
