#include "lib/run_folder.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "lib/atomic_file.hpp"

namespace tissu {
namespace fs = std::filesystem;
namespace {

/// The "name" of the scenario.json in `dir`, or "" when there is none or it cannot be read.
std::string earlier_run_name(const fs::path& dir) {
  std::ifstream in(dir / "scenario.json");
  if (!in) return "";
  const nlohmann::json earlier = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!earlier.is_object() || !earlier.contains("name") || !earlier["name"].is_string()) return "";
  return earlier["name"].get<std::string>();
}

}  // namespace

bool is_run_output_name(const std::string& name) {
  static const std::regex output(
      R"((stats\.csv|scenario\.json|run\.json|frames\.pc2|frames\.h5|frame_\d{5}\.(obj|ply|png|glb)|)"
      R"(last_good_frame_\d{5}(_step_\d{2})?\.(obj|ply)))");
  static const std::regex temporary(R"(\.(.+)\.tmp\d+_\d+)");
  std::smatch parts;
  if (std::regex_match(name, parts, temporary)) return std::regex_match(parts[1].str(), output);
  return std::regex_match(name, output);
}

int remove_earlier_run(const fs::path& dir, const std::string& video_stem) {
  if (!fs::is_directory(dir)) return 0;
  std::set<std::string> videos;
  for (const std::string& stem : {video_stem, earlier_run_name(dir)}) {
    if (stem.empty()) continue;
    videos.insert(stem + ".mp4");
    videos.insert(stem + ".gif");
  }
  std::vector<fs::path> to_remove;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && (is_run_output_name(name) || videos.count(name)))
      to_remove.push_back(entry.path());
  }
  // the browser viewer's folder (lib/viewer_frames.hpp): its three files, then the folder if empty
  for (const char* name : {"index.html", "tissu_viewer.js", "frames.js"}) {
    if (fs::is_regular_file(dir / "viewer" / name)) to_remove.push_back(dir / "viewer" / name);
  }
  for (const fs::path& file : to_remove) fs::remove(file);
  std::error_code not_empty;
  fs::remove(dir / "viewer", not_empty);  // refused when it holds anything else
  return static_cast<int>(to_remove.size());
}

void write_resolved_scenario(const fs::path& dir, const std::string& resolved_json, int frames) {
  nlohmann::json scenario = nlohmann::json::parse(resolved_json);
  scenario["simulation"]["frames"] = frames;
  write_file_atomically(
      dir / "scenario.json",
      scenario.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n",
      "resolved scenario");
}

}  // namespace tissu
