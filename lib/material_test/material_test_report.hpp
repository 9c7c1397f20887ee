#pragma once
/// \file
/// The material test (`tissu material-test`): every stiffness formulation, on every test sheet
/// it is defined on, for several target Poisson ratios, measured (effective_material.hpp) and
/// written as CSV, a markdown table and a plot.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/material_test/effective_material.hpp"
#include "lib/material_test/test_sheets.hpp"
#include "topology/material.hpp"

namespace tissu {

struct MaterialTestOptions {
  int cells = 16;                  ///< cells along each side of the 1 m sheets
  double youngs_modulus_pa = 5e5;  ///< target E (Pa)
  double thickness_m = 5e-4;       ///< h (m)
  double density_kg_per_m3 = 200;  ///< rho (kg/m^3); no influence on a static test
  std::vector<double> poisson_ratios = {0.0, 0.2, 0.3, 1.0 / 3.0, 0.45};  ///< targets
};

/// One formulation on one sheet at one target Poisson ratio.
struct MaterialTestRow {
  StiffnessFormulation formulation = StiffnessFormulation::delingette2008;
  TestSheet sheet = TestSheet::right_triangles;
  int cells = 0;
  double target_nu = 0.0;
  bool refused = false;  ///< nu outside the formulation's range: nothing measured
  EffectiveMaterial measured;
  /// A literal pull along x with free top and bottom sides; not on the equilateral sheet, whose
  /// left and right sides zigzag.
  std::optional<StripTension> strip;
};

/// Runs every formulation on every sheet whose cells it defines, at every target nu. A nu the
/// formulation refuses gives a row with refused = true.
std::vector<MaterialTestRow> run_material_tests(const MaterialTestOptions& options);

/// Writes `rows` to `dir`/material_test.csv (one line per row, every measured constant and its
/// relative error) and `dir`/material_test.md (a markdown table of the same), creating `dir`.
void write_material_tables(const std::vector<MaterialTestRow>& rows,
                           const MaterialTestOptions& options, const std::filesystem::path& dir);

/// Writes `dir`/material_test.gp and runs gnuplot on it to make `dir`/material_test.png: measured
/// against target nu, E, shear modulus and diagonal E, one line per formulation and sheet.
/// Returns an empty string, or one line saying why the PNG was not made (no gnuplot, or its
/// error).
std::string plot_material_tests(const std::vector<MaterialTestRow>& rows,
                                const MaterialTestOptions& options,
                                const std::filesystem::path& dir);

}  // namespace tissu
