#include "lib/render/video.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "lib/atomic_file.hpp"
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

/// A temporary folder holding image_00000.png, image_00001.png, ... linked (or, where links
/// cannot be made, copied) to given images, for ffmpeg's image2 reader, which needs consecutive
/// numbers; removed with the object.
class NumberedImages {
 public:
  /// Throws std::filesystem::filesystem_error when the folder or a copy cannot be made.
  explicit NumberedImages(const std::vector<fs::path>& images) {
    static int made = 0;  // one folder per call of this process
    m_dir = fs::temp_directory_path() /
            ("tissu_video_" + std::to_string(getpid()) + "_" + std::to_string(made++));
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
    for (std::size_t k = 0; k < images.size(); ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "image_%05zu.png", k);
      std::error_code error;
      fs::create_symlink(fs::absolute(images[k]), m_dir / name, error);
      if (error) fs::copy_file(images[k], m_dir / name);
    }
  }
  ~NumberedImages() {
    std::error_code ignored;
    fs::remove_all(m_dir, ignored);
  }
  NumberedImages(const NumberedImages&) = delete;
  NumberedImages& operator=(const NumberedImages&) = delete;

  /// The image2 pattern of the links.
  std::string pattern() const { return (m_dir / "image_%05d.png").string(); }

 private:
  fs::path m_dir;
};

/// The cause, when ffmpeg's error output says the disk refused its writes (no space, over the file
/// size limit or the quota): strerror's text, which ffmpeg prints.
std::optional<std::string> disk_full_cause(const std::string& errors) {
  for (const int error : {ENOSPC, EFBIG, EDQUOT}) {
    const std::string text = std::strerror(error);
    if (errors.find(text) != std::string::npos) return text;
  }
  return std::nullopt;
}

}  // namespace

VideoResult encode_video(const std::vector<fs::path>& frames, double frame_rate,
                         const fs::path& mp4, const fs::path& gif, StopRequest stop) {
  if (!(frame_rate > 0.0) || !std::isfinite(frame_rate))
    throw std::invalid_argument("encode_video: frame rate must be positive, got " +
                                rate_text(frame_rate));
  if (mp4.empty() && gif.empty()) return {true, ""};
  if (frames.empty()) return {false, "no video made: no images to encode"};
  const std::optional<fs::path> ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg) {
    return {false, "ffmpeg not found on PATH: no video made; frames are in " +
                       frames.front().parent_path().string()};
  }
  for (const fs::path& frame : frames) {
    std::error_code error;
    if (!fs::is_regular_file(frame, error))
      return {false, "no video made: " + frame.string() + " is not a file"};
  }
  std::optional<NumberedImages> numbered;
  try {
    numbered.emplace(frames);
  } catch (const fs::filesystem_error& e) {
    return {false, std::string("no video made: cannot number the images for ffmpeg: ") + e.what()};
  }

  const std::vector<std::string> input = {
      "-hide_banner",        "-nostdin", "-loglevel",        "error", "-y", "-framerate",
      rate_text(frame_rate), "-i",       numbered->pattern()};
  std::vector<std::string> warnings;
  bool stopped = false;
  // ffmpeg writes a temporary file beside the output, renamed once ffmpeg succeeded (so that a
  // failed or stopped encoding leaves no truncated video); its format is given, since the
  // temporary's name does not end in .mp4 or .gif
  const auto encode = [&](const fs::path& output, const char* what, const char* format,
                          const std::vector<std::string>& options) {
    if (output.empty() || stopped) return;
    if (stop.requested()) {
      stopped = true;
      return;
    }
    PendingFile pending(output, std::string(format) + " video");
    std::vector<std::string> arguments = input;
    arguments.insert(arguments.end(), options.begin(), options.end());
    arguments.insert(arguments.end(), {"-f", format, pending.temporary().string()});
    const ProgramResult result = run_program(*ffmpeg, arguments, stop);
    if (result.stopped || stop.requested()) {  // Ctrl-C reaches ffmpeg too, which then fails
      stopped = true;
      return;
    }
    // a full disk is not ffmpeg's failure but the run's: it stops it, as for any other file.
    // ffmpeg 5.1 reports a failed write ("Error writing trailer of ...: File too large") and
    // still exits 0, so its error output decides, whatever its status
    if (const auto cause = disk_full_cause(result.errors))
      throw FileWriteError(output, std::string(format) + " video", *cause);
    if (result.status == 0) {
      try {
        pending.commit();
      } catch (const FileWriteError& e) {
        warnings.push_back(std::string("cannot make ") + what + ": " + e.what());
      }
      return;
    }
    warnings.push_back(std::string("ffmpeg failed to make ") + what + " " + output.string() +
                       " (exit status " + std::to_string(result.status) +
                       "): " + last_output(result.errors));
  };
  encode(mp4, "the MP4", "mp4",
         {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20", "-movflags", "+faststart"});
  const std::string gif_rate = rate_text(std::min(frame_rate, 15.0));
  encode(gif, "the GIF", "gif",
         {"-filter_complex",
          "fps=" + gif_rate +
              ",scale=w=min(320\\,iw):h=-1:flags=lanczos,split[a][b];[a]palettegen[p];"
              "[b][p]paletteuse",
          "-loop", "0"});

  if (stopped) return {false, "no video made: stopped", true};
  VideoResult result{warnings.empty(), ""};
  for (const std::string& w : warnings) result.warning += (result.warning.empty() ? "" : "; ") + w;
  return result;
}

}  // namespace tissu
