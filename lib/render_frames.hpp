#pragma once
/// \file
/// Renders the frames of a run to PNG files with one camera, then a video. CGAL-free.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/stop_request.hpp"
#include "topology/indexed_mesh.hpp"

namespace tissu {

/// What one image shows.
struct RenderFrame {
  IndexedMesh mesh;                  ///< the cloth's surface
  std::vector<std::uint8_t> pinned;  ///< #V, 1 for pinned particles; may be empty
  std::vector<float> face_strain;    ///< #F mean edge strain; may be empty (dimensionless)
  // the two below are brace-initialised so that frames listed without them stay -Wextra clean
  std::vector<IndexedMesh> obstacles{};   ///< closed meshes, where they are at the frame's time
  std::vector<float> face_level{};        ///< #F refinement level, log2(A_input / A); may be empty
  std::vector<float> face_sizing_term{};  ///< #F SizingTerm that held the face; may be empty
  std::optional<double> ground_height_m{};  ///< height (z, m) of a floor plane, if any
  int frame{0};  ///< the frame of the run it shows, which names its image: frame_NNNNN.png
};

struct RenderedRun {
  int images = 0;             ///< PNG files written, frame_NNNNN.png named by RenderFrame::frame
  bool video = false;         ///< whether the MP4 and GIF were made
  std::string video_warning;  ///< why not, when video was asked for but not made
  bool stopped = false;       ///< `stop` was requested: the images so far written, no video
};

/// Writes each of `frames` to output_dir/frame_NNNNN.png, NNNNN its RenderFrame::frame (5 digits
/// or more), with settings.camera, or a camera that frames the bounding box of every frame's cloth
/// (not its obstacles), then, if settings.video, output_dir/<video_stem>.mp4 and .gif of those
/// images in the order given, at `images_per_second`. Calls on_image(done, total) after each
/// image. Checks `stop` before each image and while the video is made: when it is requested,
/// returns with stopped = true, every image written so far complete, and no video. Every file is
/// written whole or not at all (lib/atomic_file.hpp); FileWriteError when the disk refuses one.
RenderedRun render_frames(const std::vector<RenderFrame>& frames, const RenderSettings& settings,
                          double images_per_second, const std::filesystem::path& output_dir,
                          const std::string& video_stem,
                          const std::function<void(int, int)>& on_image = {},
                          StopRequest stop = {});

}  // namespace tissu
