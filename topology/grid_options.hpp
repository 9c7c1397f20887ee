#pragma once
/// \file
/// How a rectangular cloth grid is laid out. CGAL-free.

#include <Eigen/Core>

namespace tissu {

enum class GridCells { triangles, quads };

/// Which diagonal splits each grid cell into two triangles.
enum class DiagonalPattern {
  forward,      ///< every cell split from (i,j) to (i+1,j+1)
  backward,     ///< every cell split from (i+1,j) to (i,j+1)
  alternating,  ///< checkerboard of both: no preferred shear direction
};

/// A width x height rectangle spanned from `origin` along the unit axes u and v, cut into
/// cells_u x cells_v cells. Vertex (i, j) has index j (cells_u + 1) + i and material coordinates
/// origin + i du u + j dv v. Its sides are named in this frame: left/right along u, bottom/top
/// along v.
struct GridOptions {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< corner (i, j) = (0, 0) (m)
  Eigen::Vector3d u_axis{1.0, 0.0, 0.0};             ///< width direction, unit
  Eigen::Vector3d v_axis{0.0, 0.0, 1.0};             ///< height direction, unit, orthogonal to u
  double width = 1.0;                                ///< along u (m)
  double height = 1.0;                               ///< along v (m)
  int cells_u = 16;                                  ///< cells along u
  int cells_v = 16;                                  ///< cells along v
  GridCells cells = GridCells::triangles;
  /// Start gathered into this many pleats along u (a curtain on its rail); 0 starts flat. The
  /// rest shape stays flat either way.
  int pleats = 0;
  double gathered_width = 0.0;  ///< width along u the pleats gather the cloth into (m), < width
  DiagonalPattern diagonal = DiagonalPattern::alternating;  ///< triangles only
};

}  // namespace tissu
