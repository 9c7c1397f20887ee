#include "apps/render_command.hpp"

#include <unistd.h>

#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "apps/stop_signals.hpp"
#include "lib/progress.hpp"
#include "lib/render_folder.hpp"

namespace tissu {

void add_render_options(CLI::App& app, RenderCommand& command) {
  RenderOptions& o = command.settings.options;
  app.add_option("mesh_dir", command.mesh_dir, "folder of frame_NNNNN.obj or .ply meshes")
      ->required();
  app.add_option("-o,--out", command.output_dir, "where PNG frames go (default: the mesh folder)");
  app.add_option("--width", o.width, "image width in pixels, even")->capture_default_str();
  app.add_option("--height", o.height, "image height in pixels, even")->capture_default_str();
  app.add_flag("--wireframe", o.wireframe, "draw the mesh edges");
  app.add_option("--fps", command.frame_rate, "video frame rate (Hz)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_flag("--no-video", command.no_video, "PNG frames only, no MP4 or GIF");
  // the scenario's render.camera, in the same units; unset, the camera frames the whole run
  CLI::Option* position =
      app.add_option("--camera-position", command.camera_position, "camera eye X Y Z (m)")
          ->expected(3);
  CLI::Option* target =
      app.add_option("--camera-target", command.camera_target,
                     "point X Y Z at the image centre (m); with --camera-position")
          ->expected(3);
  position->needs(target);
  target->needs(position);
  app.add_option("--camera-up", command.camera_up, "image-up hint X Y Z")
      ->expected(3)
      ->needs(position)
      ->capture_default_str();
  app.add_option("--camera-fov", command.camera_fov_deg, "vertical field of view (degrees)")
      ->check(CLI::Range(0.0, 179.0))
      ->needs(position)
      ->capture_default_str();
  app.add_flag("-q,--quiet", command.quiet, "no progress output");
}

namespace {

Eigen::Vector3d vector3(const std::vector<double>& xyz) {
  return {xyz.at(0), xyz.at(1), xyz.at(2)};
}

/// The camera the options give, if any; throws std::invalid_argument naming the option when it
/// is not a usable camera.
std::optional<Camera> command_camera(const RenderCommand& command) {
  if (command.camera_position.empty()) return std::nullopt;
  Camera camera;
  camera.position = vector3(command.camera_position);
  camera.target = vector3(command.camera_target);
  camera.up = vector3(command.camera_up);
  camera.fov_y_deg = command.camera_fov_deg;
  try {
    validate_camera(camera);
  } catch (const std::invalid_argument& e) {
    std::string what = e.what();  // "camera: target equals position"
    if (what.rfind("camera: ", 0) == 0) what.erase(0, 8);
    throw std::invalid_argument("render: --camera-position, --camera-target, --camera-up: " + what);
  }
  return camera;
}

}  // namespace

int execute(const RenderCommand& command) {
  // SIGINT and SIGTERM stop after the image in progress (apps/stop_signals.hpp)
  const StopRequest stop = install_stop_signals();
  try {
    RenderSettings settings = command.settings;
    settings.enabled = true;
    settings.video = !command.no_video;
    settings.camera = command_camera(command);
    validate_render_options(settings.options);
    const std::filesystem::path out =
        command.output_dir.empty() ? command.mesh_dir : command.output_dir;
    ProgressReporter progress = stderr_progress();
    std::function<void(int, int)> on_image;
    if (!command.quiet)
      on_image = [&progress](int done, int total) { progress.rendered(done, total); };
    const RenderedRun run =
        render_mesh_folder(command.mesh_dir, settings, command.frame_rate, out, on_image, stop);
    if (run.stopped) {
      const int signal_number = *stop.flag;
      const bool mid_line = !command.quiet && isatty(STDERR_FILENO) == 1;
      std::fprintf(stderr, "%stissu: stopped by %s: %d complete images in %s, no video\n",
                   mid_line ? "\n" : "", signal_name(signal_number), run.images, out.c_str());
      return stopped_exit_status(signal_number);
    }
    if (!run.video_warning.empty()) {
      std::fprintf(stderr, "tissu: warning: %s\n", run.video_warning.c_str());
    }
    if (!command.quiet) {
      std::fprintf(stderr, "tissu: %d images written to %s\n", run.images, out.c_str());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tissu: %s\n", e.what());
    return 1;
  }
}

}  // namespace tissu
