#include "apps/material_test_command.hpp"

#include <cstdio>

namespace tissu {

void add_material_test_options(CLI::App& app, MaterialTestCommand& command) {
  MaterialTestOptions& o = command.options;
  app.add_option(
         "-o,--out", command.output_dir,
         "folder for material_test.csv, material_test.md, material_test.gp and material_test.png")
      ->capture_default_str();
  app.add_option("--cells", o.cells, "cells along each side of the 1 m test sheets")
      ->check(CLI::Range(2, 512))
      ->capture_default_str();
  app.add_option("--E", o.youngs_modulus_pa, "target Young's modulus (Pa)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--thickness", o.thickness_m, "sheet thickness (m)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--nu", o.poisson_ratios, "target Poisson ratios")
      ->check(CLI::Range(-0.99, 0.499))
      ->capture_default_str();
  app.add_flag("-q,--quiet", command.quiet, "no summary output");
}

int execute(const MaterialTestCommand& command) {
  try {
    const std::vector<MaterialTestRow> rows = run_material_tests(command.options);
    write_material_tables(rows, command.options, command.output_dir);
    const std::string plot_warning = plot_material_tests(rows, command.options, command.output_dir);
    if (!plot_warning.empty()) std::fprintf(stderr, "tissu: warning: %s\n", plot_warning.c_str());
    if (!command.quiet) {
      std::fprintf(stderr, "tissu: %zu material tests written to %s\n", rows.size(),
                   command.output_dir.c_str());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tissu: error: %s\n", e.what());
  }
  return 1;
}

}  // namespace tissu
