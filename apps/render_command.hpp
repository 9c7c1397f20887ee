#pragma once
// The tissu CLI's render command: re-render a folder of saved frame meshes.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"

namespace tissu {

struct RenderCommand {
  std::string mesh_dir;
  std::string output_dir;    ///< empty: the mesh folder
  double frame_rate = 30.0;  ///< images per second of the video (Hz)
  bool no_video = false;
  bool quiet = false;
  RenderSettings settings;
  /// --camera-position and --camera-target (m, 3 values each, both or neither), --camera-up and
  /// --camera-fov: the scenario's render.camera; unset, the camera frames every frame's cloth
  std::vector<double> camera_position, camera_target;
  std::vector<double> camera_up{0.0, 0.0, 1.0};  ///< image-up hint
  double camera_fov_deg = 40.0;                  ///< vertical field of view (degrees)
};

/// Adds the render subcommand's arguments and options to `app`: the mesh folder, --out, image
/// size, --wireframe, --fps, --no-video, --quiet and the camera (--camera-position,
/// --camera-target, --camera-up, --camera-fov).
void add_render_options(CLI::App& app, RenderCommand& command);

/// Renders; prints errors as one line on stderr. Returns 0 on success, 1 on bad input.
int execute(const RenderCommand& command);

}  // namespace tissu
