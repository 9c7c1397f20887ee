#include "lib/viewer_frames.hpp"

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace tissu {
namespace {

namespace fs = std::filesystem;

/// RFC 4648 base64 of `count` values of `T`, the form the page decodes with atob().
template <class T>
std::string base64(const T* values, std::size_t count) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = reinterpret_cast<const unsigned char*>(values);
  const std::size_t size = count * sizeof(T);
  std::string text;
  text.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const unsigned b0 = bytes[i];
    const unsigned b1 = i + 1 < size ? bytes[i + 1] : 0;
    const unsigned b2 = i + 2 < size ? bytes[i + 2] : 0;
    const unsigned triple = (b0 << 16) | (b1 << 8) | b2;
    text += alphabet[(triple >> 18) & 63];
    text += alphabet[(triple >> 12) & 63];
    text += i + 1 < size ? alphabet[(triple >> 6) & 63] : '=';
    text += i + 2 < size ? alphabet[triple & 63] : '=';
  }
  return text;
}

std::string positions_base64(const std::vector<Eigen::Vector3d>& points) {
  std::vector<float> xyz;
  xyz.reserve(3 * points.size());
  for (const Eigen::Vector3d& p : points)
    xyz.insert(xyz.end(), {float(p.x()), float(p.y()), float(p.z())});
  return base64(xyz.data(), xyz.size());
}

/// The triangles of `faces` (a quad split along its first diagonal), and the face of each.
std::vector<std::uint32_t> triangles_of(const std::vector<std::vector<int>>& faces,
                                        std::vector<int>* face_of_triangle = nullptr) {
  std::vector<std::uint32_t> triangles;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (std::size_t k = 1; k + 1 < faces[f].size(); ++k) {
      triangles.insert(triangles.end(), {std::uint32_t(faces[f][0]), std::uint32_t(faces[f][k]),
                                         std::uint32_t(faces[f][k + 1])});
      if (face_of_triangle) face_of_triangle->push_back(static_cast<int>(f));
    }
  }
  return triangles;
}

void copy_page_file(const fs::path& name, const fs::path& viewer_dir) {
  const fs::path from = viewer_assets_dir() / name;
  std::error_code error;
  if (!fs::is_regular_file(from, error)) {
    throw std::runtime_error(from.string() +
                             ": the viewer page was not built (run scripts/setup.sh, which "
                             "installs its npm packages, then build again), or set "
                             "output.viewer to false");
  }
  std::ifstream in(from, std::ios::binary);
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  write_file_atomically(viewer_dir / name, page, "viewer page");  // whole, even on a full disk
}

/// `viewer_dir`/frames.js, the folder created first.
fs::path frames_file(const fs::path& viewer_dir) {
  fs::create_directories(viewer_dir);
  return viewer_dir / "frames.js";
}

}  // namespace

fs::path viewer_assets_dir() {
  return TISSU_VIEWER_ASSETS_DIR;
}

ViewerFramesFile::ViewerFramesFile(const fs::path& viewer_dir, const std::string& run_name)
    : m_file(frames_file(viewer_dir), "viewer frames") {
  copy_page_file("index.html", viewer_dir);
  copy_page_file("tissu_viewer.js", viewer_dir);
  nlohmann::json columns = nlohmann::json::array();
  for (const StatsColumn& column : stats_columns(FrameStats{})) columns.push_back(column.name);
  m_file.append(
      "tissu.run(" +
      nlohmann::json(run_name).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) +
      ", " + columns.dump() + ");\n");
}

void ViewerFramesFile::append(const RenderFrame& frame, const FrameStats& row) {
  nlohmann::json f;
  f["frame"] = frame.frame;
  nlohmann::json stats;
  for (const StatsColumn& column : stats_columns(row)) stats[column.name] = column.value;
  f["stats"] = stats;
  f["positions"] = positions_base64(frame.mesh.vertices);
  std::vector<int> face_of_triangle;
  std::vector<std::uint32_t> triangles = triangles_of(frame.mesh.faces, &face_of_triangle);
  // per triangle, from per face (0 where the frame has none)
  auto per_triangle = [&](const std::vector<float>& per_face) {
    std::vector<float> values(face_of_triangle.size(), 0.0f);
    if (per_face.size() == frame.mesh.faces.size()) {
      for (std::size_t t = 0; t < values.size(); ++t) values[t] = per_face[face_of_triangle[t]];
    }
    return base64(values.data(), values.size());
  };
  if (triangles != m_triangles) {  // the level changes only with the triangles
    f["triangles"] = base64(triangles.data(), triangles.size());
    f["level"] = per_triangle(frame.face_level);
    m_triangles = std::move(triangles);
  }
  f["strain"] = per_triangle(frame.face_strain);
  std::vector<int> pinned;
  for (std::size_t v = 0; v < frame.pinned.size(); ++v)
    if (frame.pinned[v]) pinned.push_back(static_cast<int>(v));
  if (pinned != m_pinned || row.frame == 0) {
    f["pinned"] = pinned;
    m_pinned = std::move(pinned);
  }
  nlohmann::json obstacles = nlohmann::json::array();
  for (const IndexedMesh& obstacle : frame.obstacles) {
    const std::vector<std::uint32_t> t = triangles_of(obstacle.faces);
    obstacles.push_back({{"positions", positions_base64(obstacle.vertices)},
                         {"triangles", base64(t.data(), t.size())}});
  }
  if (!obstacles.empty()) f["obstacles"] = obstacles;
  m_file.append("tissu.frame(" + f.dump() + ");\n");
}

}  // namespace tissu
