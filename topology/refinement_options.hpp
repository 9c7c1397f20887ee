#pragma once
/// \file
/// When and how far the cloth is refined. CGAL-free.

namespace tissu {

struct RefinementOptions {
  /// Refine around edges whose engineering strain |l / l0 - 1| exceeds this (dimensionless);
  /// 0 disables the criterion.
  double strain_threshold = 0.0;
  /// Refine around interior edges whose two faces' normals differ by more than this angle
  /// (radians); 0 disables the criterion.
  double curvature_threshold_rad = 0.0;
  /// Never create edges shorter than this in rest space (m): an edge is split only if its rest
  /// length is at least twice this.
  double min_edge_length_m = 0.01;
  /// Refine edges longer than this in rest space (m), whatever the criteria, and never coarsen
  /// back to them; 0 sets no maximum.
  double max_edge_length_m = 0.0;
  /// Stop refining when the cloth has this many particles.
  int max_particles = 100000;
};

/// What one refinement pass did.
struct RefinementReport {
  int splits = 0;           ///< edges bisected
  int candidate_edges = 0;  ///< edges over a threshold
};

}  // namespace tissu
