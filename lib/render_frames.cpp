#include "lib/render_frames.hpp"

#include <cstdio>

#include "lib/render/image.hpp"
#include "lib/render/renderer.hpp"
#include "lib/render/video.hpp"

namespace tissu {
namespace {

/// The box the automatic camera frames: the cloth over the whole run. Obstacles are left out on
/// purpose: the cloth is the subject, and what it drapes over (the drape scene's ball) lies inside
/// the box it sweeps anyway, while a big obstacle (a table-sized box, a long capsule) would shrink
/// the cloth to a few pixels. Planes have no mesh and would be unbounded.
Eigen::AlignedBox3d bounds_of(const std::vector<RenderFrame>& frames) {
  Eigen::AlignedBox3d box;
  for (const RenderFrame& frame : frames) {
    for (const Eigen::Vector3d& p : frame.mesh.vertices) box.extend(p);
  }
  return box;
}

}  // namespace

RenderedRun render_frames(const std::vector<RenderFrame>& frames, const RenderSettings& settings,
                          double images_per_second, const std::filesystem::path& output_dir,
                          const std::string& video_stem,
                          const std::function<void(int, int)>& on_image, StopRequest stop) {
  RenderedRun run;
  if (frames.empty()) return run;
  const RenderOptions& options = settings.options;
  const double aspect = double(options.width) / options.height;
  const Camera camera = settings.camera.value_or(framing_camera(bounds_of(frames), aspect));
  Renderer renderer(options);
  const int total = static_cast<int>(frames.size());
  std::vector<std::filesystem::path> images;
  for (int k = 0; k < total; ++k) {
    if (stop.requested()) {
      run.stopped = true;
      return run;
    }
    RenderScene scene;
    scene.mesh = &frames[k].mesh;
    scene.pinned = frames[k].pinned;
    scene.face_strain = frames[k].face_strain;
    scene.face_level = frames[k].face_level;
    scene.face_sizing_term = frames[k].face_sizing_term;
    scene.obstacles = frames[k].obstacles;
    scene.ground_height_m = frames[k].ground_height_m;
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frames[k].frame);
    images.push_back(output_dir / name);
    write_png(images.back(), renderer.render(scene, camera));
    run.images = k + 1;
    if (on_image) on_image(k + 1, total);
  }
  if (settings.video) {
    const VideoResult video =
        encode_video(images, images_per_second, output_dir / (video_stem + ".mp4"),
                     output_dir / (video_stem + ".gif"), stop);
    run.stopped = video.stopped;
    run.video = video.made;
    run.video_warning = video.warning;
  }
  return run;
}

}  // namespace tissu
