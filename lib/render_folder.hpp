#pragma once
/// \file
/// Re-renders the frame meshes a run saved, without simulating again.

#include <filesystem>
#include <functional>

#include "lib/render_frames.hpp"

namespace tissu {

/// The frame meshes of `mesh_dir` (frame_NNNNN.obj or .ply), in frame order. Throws
/// std::runtime_error when there are none, MeshError when one cannot be read.
std::vector<std::filesystem::path> frame_mesh_files(const std::filesystem::path& mesh_dir);

/// Renders every frame mesh of `mesh_dir` into output_dir as render_frames() does, the video named
/// after the folder.
RenderedRun render_mesh_folder(const std::filesystem::path& mesh_dir,
                               const RenderSettings& settings, double images_per_second,
                               const std::filesystem::path& output_dir,
                               const std::function<void(int, int)>& on_image = {});

}  // namespace tissu
