#pragma once
// The tissu CLI's view command: where a run's browser viewer is (lib/viewer_frames.hpp).

#include <CLI/CLI.hpp>
#include <string>

namespace tissu {

struct ViewCommand {
  std::string run_folder;
};

/// Adds the view subcommand's argument to `app`: the run folder.
void add_view_options(CLI::App& app, ViewCommand& command);

/// Prints the file:// address of the run folder's viewer page on stdout (to open in a browser)
/// and how many frames it plays on stderr. Returns 0, or 1 after one error line when the folder
/// has no viewer.
int execute(const ViewCommand& command);

}  // namespace tissu
