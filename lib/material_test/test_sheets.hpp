#pragma once
/// \file
/// The sheets the material test stretches: 1 m x 1 m in the xy plane, cut into cells of several
/// shapes, so that a formulation's dependence on the mesh shows.

#include <string_view>

#include "topology/cloth_complex.hpp"
#include "topology/spring_settings.hpp"

namespace tissu {

enum class TestSheet {
  right_triangles,        ///< square cells cut along alternating diagonals (the default grid)
  equilateral_triangles,  ///< rows of equilateral triangles, every other row shifted by half
  quads,                  ///< square cells
  refined_triangles,      ///< right_triangles bisected around two points (irregular triangles)
};
inline constexpr int test_sheet_count = 4;

/// Name in tables ("right_triangles", ...).
std::string_view to_string(TestSheet sheet);

/// Whether the sheet's cells are quads.
inline bool has_quads(TestSheet sheet) {
  return sheet == TestSheet::quads;
}

/// Builds the sheet with about `cells` cells along each side into `lcc`: structural and shear
/// springs from `material` (bending springs, which carry no in-plane load, left out) and its
/// areal density.
void build_test_sheet(TestSheet sheet, int cells, const Material& material, ClothComplex& lcc);

}  // namespace tissu
