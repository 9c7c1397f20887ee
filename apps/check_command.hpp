#pragma once
// The tissu CLI's check command: validate a scenario, its meshes and pins, without running it.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace tissu {

struct CheckCommand {
  std::string scenario;
  std::vector<std::string> overrides;
};

/// Adds the check subcommand's arguments to `app`: the scenario and --set.
void add_check_options(CLI::App& app, CheckCommand& command);

/// Loads the scenario and builds its cloth as `tissu run` would; prints the resolved scenario
/// (every default filled in) on stdout and a one-line summary of the cloth on stderr. Returns 0
/// when it would run, 1 (after one error line on stderr) when not.
int execute(const CheckCommand& command);

}  // namespace tissu
