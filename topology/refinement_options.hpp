#pragma once
/// \file
/// When and how far the cloth is refined: the terms of the sizing field (sizing_field.hpp) and the
/// bounds on edge lengths and particles. CGAL-free.

#include <cstdint>

namespace tissu {

/// The term of the sizing field (sizing_field.hpp) that sets a face's target edge length where it
/// holds the face (else none: the field would let coarsening merge the face back).
enum class SizingTerm : std::uint8_t {
  none,             ///< no term asks for cells this fine
  curvature,        ///< curvature relative to rest, now
  velocity,         ///< curvature the velocities make `lookahead` ahead, above today's
  strain,           ///< an edge strained or compressed past the threshold
  obstacles,        ///< an obstacle close under a face at an angle, or curved
  max_edge_length,  ///< the maximum edge length alone
};

struct RefinementOptions {
  /// Strain term: faces with an edge whose engineering strain |l / l0 - 1| exceeds this
  /// (dimensionless) want edges shorter than their own; 0 disables the term.
  double strain_threshold = 0.0;
  /// Curvature term: the angle (rad) the cloth may turn, relative to its rest shape, along one
  /// edge: an edge of rest length L is split where kappa L exceeds it, kappa the curvature of the
  /// current shape relative to the rest shape (about 2 to 3 times the dihedral angle across an edge
  /// of a grid). 0 disables the term.
  double curvature_threshold_rad = 0.0;
  /// Velocity term: the curvature term also looks at the shape the velocities make this far ahead,
  /// x + lookahead v (s): motion that will fold is refined before it folds. 0 disables the term.
  double lookahead_s = 0.0;
  /// Obstacle term: refine where the cloth's height above its nearest obstacle changes along an
  /// edge by more than the height itself (a fold about to land, a curved contact).
  bool obstacle_proximity = true;
  /// Never create edges shorter than this in rest space (m): an edge is split only if its rest
  /// length is at least twice this.
  double min_edge_length_m = 0.01;
  /// Refine edges longer than this in rest space (m), whatever the criteria, and never coarsen
  /// back to them; 0 sets no maximum.
  double max_edge_length_m = 0.0;
  /// Remeshing: false bisects triangles at their longest edge and undoes bisections (refine.hpp,
  /// coarsen.hpp); true follows an anisotropic sizing metric with splits, flips and collapses
  /// (remesh.hpp), so that cells may be long along a fold and short across it.
  bool anisotropic = false;
  /// Anisotropic remeshing: the longest a cell may be for its width, as the ratio of the
  /// metric's largest to smallest target edge length (ARCSim's 1 / aspect_min, 5 by default there).
  double max_aspect_ratio = 5.0;
  /// Stop refining when the cloth has this many particles.
  int max_particles = 100000;
  /// Undo a bisection only after this many adaptation passes in a row found it calm (>= 1).
  int coarsen_after_passes = 1;
};

/// What one refinement pass did.
struct RefinementReport {
  int splits = 0;           ///< edges bisected
  int candidate_faces = 0;  ///< triangles coarser than the sizing field wants
};

}  // namespace tissu
