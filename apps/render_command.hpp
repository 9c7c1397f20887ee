#pragma once
// The tissu CLI's render command: re-render a folder of saved frame meshes.

#include <CLI/CLI.hpp>
#include <string>

#include "lib/scenario/scenario.hpp"

namespace tissu {

struct RenderCommand {
  std::string mesh_dir;
  std::string output_dir;    ///< empty: the mesh folder
  double frame_rate = 30.0;  ///< images per second of the video (Hz)
  bool no_video = false;
  bool quiet = false;
  RenderSettings settings;
};

/// Adds the render subcommand's arguments and options to `app`.
void add_render_options(CLI::App& app, RenderCommand& command);

/// Renders; prints errors as one line on stderr. Returns 0 on success, 1 on bad input.
int execute(const RenderCommand& command);

}  // namespace tissu
