#include "lib/render/video.hpp"

#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "lib/render/external_program.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;

std::string rate_text(double frame_rate) {
  std::ostringstream out;
  out.precision(10);
  out << frame_rate;
  return out.str();
}

}  // namespace

VideoResult encode_video(const fs::path& frames_dir, double frame_rate, const fs::path& mp4,
                         const fs::path& gif) {
  if (!(frame_rate > 0.0) || !std::isfinite(frame_rate))
    throw std::invalid_argument("encode_video: frame rate must be positive, got " +
                                rate_text(frame_rate));
  if (mp4.empty() && gif.empty()) return {true, ""};
  const std::optional<fs::path> ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg)
    return {false, "ffmpeg not found on PATH: no video made; frames are in " + frames_dir.string()};
  std::error_code error;
  if (!fs::is_regular_file(frames_dir / "frame_00000.png", error))
    return {false, "no video made: " + frames_dir.string() + " has no frame_00000.png"};

  const std::vector<std::string> input = {"-hide_banner",
                                          "-nostdin",
                                          "-loglevel",
                                          "error",
                                          "-y",
                                          "-framerate",
                                          rate_text(frame_rate),
                                          "-i",
                                          (frames_dir / "frame_%05d.png").string()};
  std::vector<std::string> warnings;
  const auto encode = [&](const fs::path& output, const char* what,
                          const std::vector<std::string>& options) {
    if (output.empty()) return;
    std::vector<std::string> arguments = input;
    arguments.insert(arguments.end(), options.begin(), options.end());
    arguments.push_back(output.string());
    const ProgramResult result = run_program(*ffmpeg, arguments);
    if (result.status != 0)
      warnings.push_back(std::string("ffmpeg failed to make ") + what + " " + output.string() +
                         " (exit status " + std::to_string(result.status) +
                         "): " + last_output(result.errors));
  };
  encode(mp4, "the MP4",
         {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20", "-movflags", "+faststart"});
  const std::string gif_rate = rate_text(std::min(frame_rate, 15.0));
  encode(gif, "the GIF",
         {"-filter_complex",
          "fps=" + gif_rate +
              ",scale=w=min(320\\,iw):h=-1:flags=lanczos,split[a][b];[a]palettegen[p];"
              "[b][p]paletteuse",
          "-loop", "0"});

  VideoResult result{warnings.empty(), ""};
  for (const std::string& w : warnings) result.warning += (result.warning.empty() ? "" : "; ") + w;
  return result;
}

}  // namespace tissu
