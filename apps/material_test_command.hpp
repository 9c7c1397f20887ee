#pragma once
// The tissu CLI's material-test command: measure every stiffness formulation against its target.

#include <CLI/CLI.hpp>
#include <string>

#include "lib/material_test/material_test_report.hpp"

namespace tissu {

struct MaterialTestCommand {
  std::string output_dir = "material-test";
  MaterialTestOptions options;
  bool quiet = false;
};

/// Adds the material-test subcommand's options to `app`.
void add_material_test_options(CLI::App& app, MaterialTestCommand& command);

/// Runs the tests and writes the tables and plot; errors as one line on stderr. Returns 0 on
/// success, 1 on failure.
int execute(const MaterialTestCommand& command);

}  // namespace tissu
