#pragma once
// The tissu CLI's sweep command: a sweep file run by the Python package's tissu.sweep
// (python/tissu/sweep.py), on a local process pool or a Dask cluster.

#include <CLI/CLI.hpp>
#include <string>

namespace tissu {

struct SweepCommand {
  std::string sweep;
  std::string scheduler;  ///< a Dask scheduler's address, or empty for local processes
  int workers = 0;        ///< local processes, 0 for the cores
};

/// Adds the sweep subcommand's arguments to `app`: the sweep file, --scheduler, --workers.
void add_sweep_options(CLI::App& app, SweepCommand& command);

/// Replaces this process by `python3 -m tissu.sweep` with the built package on PYTHONPATH.
/// Returns 1, after one error line, when that cannot start (no Python package was built).
int execute(const SweepCommand& command);

}  // namespace tissu
