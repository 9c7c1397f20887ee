#include "lib/material_test/test_sheets.hpp"

#include <cmath>

#include "topology/build_cloth_complex.hpp"
#include "topology/complex_navigation.hpp"
#include "topology/grid_mesh.hpp"
#include "topology/refine.hpp"

namespace tissu {
namespace {

/// Rows of equilateral triangles of side 1/cells m, rows sqrt(3)/2 of a side apart and every
/// other row shifted by half a side; as many rows as fit in 1 m (its left and right sides zigzag).
IndexedMesh equilateral_sheet(int cells) {
  const double side_m = 1.0 / cells;
  const int rows = static_cast<int>(std::round(1.0 / (side_m * std::sqrt(3.0) / 2.0)));
  IndexedMesh mesh;
  const auto id = [cells](int column, int row) { return row * (cells + 1) + column; };
  for (int row = 0; row <= rows; ++row) {
    const double shift = (row % 2) * 0.5 * side_m;
    for (int column = 0; column <= cells; ++column) {
      mesh.vertices.emplace_back(column * side_m + shift, row * side_m * std::sqrt(3.0) / 2.0, 0.0);
    }
  }
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < cells; ++column) {
      const int a = id(column, row), b = id(column + 1, row);
      const int c = id(column, row + 1), d = id(column + 1, row + 1);
      if (row % 2 == 0) {  // the row above is shifted right
        mesh.faces.push_back({a, b, c});
        mesh.faces.push_back({b, d, c});
      } else {  // the row above is shifted left
        mesh.faces.push_back({a, d, c});
        mesh.faces.push_back({a, b, d});
      }
    }
  }
  return mesh;
}

GridOptions square_grid(int cells, GridCells kind) {
  GridOptions o;
  o.width = o.height = 1.0;
  o.cells_u = o.cells_v = cells;
  o.cells = kind;
  o.diagonal = DiagonalPattern::alternating;
  o.v_axis = {0.0, 1.0, 0.0};
  return o;
}

}  // namespace

std::string_view to_string(TestSheet sheet) {
  switch (sheet) {
    case TestSheet::right_triangles:
      return "right_triangles";
    case TestSheet::equilateral_triangles:
      return "equilateral_triangles";
    case TestSheet::quads:
      return "quads";
    case TestSheet::refined_triangles:
      return "refined_triangles";
  }
  return "?";
}

void build_test_sheet(TestSheet sheet, int cells, const Material& material, ClothComplex& lcc) {
  SpringSettings springs;
  springs.structural.enabled = springs.shear.enabled = true;
  springs.material = material;
  const IndexedMesh mesh =
      sheet == TestSheet::equilateral_triangles
          ? equilateral_sheet(cells)
          : make_grid_mesh(
                square_grid(cells, has_quads(sheet) ? GridCells::quads : GridCells::triangles));
  build_cloth_complex(mesh, material.areal_density_kg_per_m2(), springs, lcc);
  if (sheet == TestSheet::refined_triangles) {
    // two levels finer around two points: triangles of several shapes and sizes
    const double finest_m = 0.25 / cells;
    for (const Eigen::Vector3d& point :
         {Eigen::Vector3d(0.3, 0.35, 0.0), Eigen::Vector3d(0.65, 0.6, 0.0)}) {
      refine_around_vertex(lcc, nearest_vertex(lcc, point), finest_m, 1'000'000, springs);
    }
  }
}

}  // namespace tissu
