#pragma once
/// \file
/// The browser viewer of a run (issue 20): OUT/viewer/index.html and tissu_viewer.js (the page
/// and its bundled three.js, viewer/), copied at the start of a run, and frames.js, to which the
/// run appends one line per recorded frame: `tissu.frame({...})` with the cloth's positions
/// (float32, m, base64), per-triangle strain, its triangles and their refinement level when they
/// changed, its pinned
/// vertices, the obstacles, and the frame's stats.csv row. A classic script, so that the page
/// plays from file:// with no server; whole lines only (AppendFile), so that a stopped run or a
/// full disk leaves a page that plays the frames before. CGAL-free.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lib/atomic_file.hpp"
#include "lib/frame_stats.hpp"
#include "lib/render_frames.hpp"

namespace tissu {

/// The folder holding the built page (index.html, tissu_viewer.js): the build's viewer/.
std::filesystem::path viewer_assets_dir();

class ViewerFramesFile {
 public:
  /// Copies the page into `viewer_dir` (created) and starts its frames.js with the run's name and
  /// the stats columns. Throws FileWriteError, or std::runtime_error when the page was not built
  /// (viewer/ needs `npm ci`, which scripts/setup.sh runs).
  ViewerFramesFile(const std::filesystem::path& viewer_dir, const std::string& run_name);
  /// Appends one frame. Throws FileWriteError (frames.js then ends with the frame before).
  void append(const RenderFrame& frame, const FrameStats& row);

 private:
  AppendFile m_file;
  std::vector<std::uint32_t> m_triangles;  ///< the last frame's, sent again only when they change
  std::vector<int> m_pinned;
};

}  // namespace tissu
