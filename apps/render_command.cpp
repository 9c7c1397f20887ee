#include "apps/render_command.hpp"

#include <cstdio>

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
  app.add_flag("-q,--quiet", command.quiet, "no progress output");
}

int execute(const RenderCommand& command) {
  try {
    RenderSettings settings = command.settings;
    settings.enabled = true;
    settings.video = !command.no_video;
    validate_render_options(settings.options);
    const std::filesystem::path out =
        command.output_dir.empty() ? command.mesh_dir : command.output_dir;
    ProgressReporter progress = stderr_progress();
    std::function<void(int, int)> on_image;
    if (!command.quiet)
      on_image = [&progress](int done, int total) { progress.rendered(done, total); };
    const RenderedRun run =
        render_mesh_folder(command.mesh_dir, settings, command.frame_rate, out, on_image);
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
