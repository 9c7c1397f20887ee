#pragma once
/// \file
/// When and where the cloth tears. CGAL-free.

#include <Eigen/Geometry>
#include <vector>

namespace tissu {

/// A part of the cloth that tears more easily: a perforation or pre-cut line (a polyline with a
/// width) or a box, both in material coordinates.
struct WeakRegion {
  enum class Kind { line, box };
  Kind kind = Kind::line;
  std::vector<Eigen::Vector3d> points_m;  ///< kind == line: the polyline's vertices (m), >= 2
  double width_m = 0.0;                   ///< kind == line: edges passing within width / 2 of
                                          ///< the polyline (crossing it, say) are weakened (m)
  Eigen::AlignedBox3d box;                ///< kind == box: edges whose midpoint lies inside (m)
  double factor = 1.0;  ///< the tearing strain is multiplied by this there, in (0, 1]
};

struct TearingOptions {
  /// An edge whose engineering strain l / l0 - 1 exceeds this breaks the cloth at one of its ends
  /// (see tear()); dimensionless, 0 disables tearing by strain.
  double strain_threshold = 0.0;
  std::vector<WeakRegion> weak_regions;  ///< the lowest factor of the regions holding an edge wins
  /// Edges unsewn per pass at most (ARCSim's max_cracks). Small values let the solver relax the
  /// cloth between tears, so that a crack grows from its tip instead of starting beside it.
  int max_tears_per_step = 1;
  /// A tear that would cut off a piece of fewer faces is not made: no loose triangles or small
  /// shreds (1 allows any piece). Scripted cuts are not limited.
  int min_piece_faces = 8;
  /// Around each crack tip, bisect edges of at least twice this rest length (m), so that the crack
  /// can turn off the initial grid's lines; 0 does not refine.
  double tip_min_edge_length_m = 0.0;
};

/// A knife cut along a polyline in material coordinates at a given time.
struct ScriptedCut {
  double time_s = 0.0;                    ///< cut at the end of the first step reaching it (s)
  std::vector<Eigen::Vector3d> points_m;  ///< >= 2 points (m)
};

/// What one tearing pass or cut did.
struct TearReport {
  int tears = 0;            ///< edges unsewn
  int new_particles = 0;    ///< particles added by vertex splits
  int tip_refinements = 0;  ///< edges bisected around crack tips
};

}  // namespace tissu
