#pragma once
/// \file
/// Re-renders the frame meshes a run saved, without simulating again.

#include <filesystem>
#include <functional>

#include "lib/render_frames.hpp"

namespace tissu {

/// The frame meshes of `mesh_dir` (frame_NNNNN.obj or .ply, 5 to 9 digits), in frame order. Throws
/// std::runtime_error when there are none.
std::vector<std::filesystem::path> frame_mesh_files(const std::filesystem::path& mesh_dir);

/// Renders every frame mesh of `mesh_dir` into output_dir as render_frames() does, each image
/// numbered as its mesh (frame_00010.obj gives frame_00010.png), the video named after the
/// folder. Throws MeshError when a mesh cannot be read. Checks `stop` between meshes read and as
/// render_frames() does: when it is requested, returns with stopped = true.
RenderedRun render_mesh_folder(const std::filesystem::path& mesh_dir,
                               const RenderSettings& settings, double images_per_second,
                               const std::filesystem::path& output_dir,
                               const std::function<void(int, int)>& on_image = {},
                               StopRequest stop = {});

}  // namespace tissu
