#include "lib/render_folder.hpp"

#include <algorithm>
#include <regex>

#include "lib/mesh_io/read_mesh.hpp"

namespace tissu {

namespace {

// 5 to 9 digits: every frame number a run writes, and no number std::stoi cannot read
const std::regex frame_name(R"(frame_(\d{5,9})\.(obj|ply))");

/// The frame number in a frame mesh's file name (frame_00042.obj: 42).
int frame_number(const std::filesystem::path& file) {
  std::smatch match;
  const std::string name = file.filename().string();
  std::regex_match(name, match, frame_name);
  return std::stoi(match[1].str());
}

}  // namespace

std::vector<std::filesystem::path> frame_mesh_files(const std::filesystem::path& mesh_dir) {
  if (!std::filesystem::is_directory(mesh_dir)) {
    throw std::runtime_error(mesh_dir.string() + ": not a folder");
  }
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(mesh_dir)) {
    if (std::regex_match(entry.path().filename().string(), frame_name)) {
      files.push_back(entry.path());
    }
  }
  if (files.empty()) {
    throw std::runtime_error(mesh_dir.string() +
                             ": no frame meshes (frame_NNNNN.obj or frame_NNNNN.ply) to render");
  }
  // by frame number: frame_100000 comes after frame_99999
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    return std::make_pair(frame_number(a), a) < std::make_pair(frame_number(b), b);
  });
  return files;
}

RenderedRun render_mesh_folder(const std::filesystem::path& mesh_dir,
                               const RenderSettings& settings, double images_per_second,
                               const std::filesystem::path& output_dir,
                               const std::function<void(int, int)>& on_image, StopRequest stop) {
  std::vector<RenderFrame> frames;
  for (const std::filesystem::path& file : frame_mesh_files(mesh_dir)) {
    if (stop.requested()) {
      RenderedRun stopped;
      stopped.stopped = true;
      return stopped;
    }
    frames.push_back(RenderFrame{read_mesh(file), {}, {}});
    frames.back().frame = frame_number(file);  // its image is named like its mesh
  }
  std::filesystem::create_directories(output_dir);
  const std::string stem =
      std::filesystem::absolute(mesh_dir).lexically_normal().filename().string();
  return render_frames(frames, settings, images_per_second, output_dir,
                       stem.empty() ? "frames" : stem, on_image, stop);
}

}  // namespace tissu
