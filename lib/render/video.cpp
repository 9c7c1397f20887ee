#include "lib/render/video.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace tissu {
namespace {

namespace fs = std::filesystem;

/// The first executable `name` in the directories of $PATH.
std::optional<fs::path> find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::istringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
    std::error_code error;
    if (fs::is_regular_file(candidate, error) && access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return std::nullopt;
}

struct RunResult {
  int status = -1;     ///< exit status, or -1 if it did not start or was killed
  std::string errors;  ///< what it wrote on stderr
};

/// Runs `program` with `arguments`, stdin and stdout on /dev/null, collecting stderr.
RunResult run(const fs::path& program, const std::vector<std::string>& arguments) {
  RunResult result;
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) {
    result.errors = "cannot create a pipe";
    return result;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[1]);

  std::vector<char*> argv;
  std::string name = program.string();
  argv.push_back(name.data());
  std::vector<std::string> copies = arguments;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);

  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, name.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  if (spawned != 0) {
    close(pipe_ends[0]);
    result.errors = "cannot start " + name;
    return result;
  }
  char buffer[4096];
  ssize_t n = 0;
  while ((n = read(pipe_ends[0], buffer, sizeof buffer)) != 0) {
    if (n > 0)
      result.errors.append(buffer, static_cast<std::size_t>(n));
    else if (errno != EINTR)
      break;
  }
  close(pipe_ends[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return result;
  }
  if (WIFEXITED(status)) result.status = WEXITSTATUS(status);
  return result;
}

/// The last few lines of `text`, on one line.
std::string tail(const std::string& text) {
  std::string flat = text;
  while (!flat.empty() && std::isspace(static_cast<unsigned char>(flat.back()))) flat.pop_back();
  if (flat.size() > 300) flat = "..." + flat.substr(flat.size() - 300);
  std::replace(flat.begin(), flat.end(), '\n', ' ');
  return flat.empty() ? "no error output" : flat;
}

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
    const RunResult result = run(*ffmpeg, arguments);
    if (result.status != 0)
      warnings.push_back(std::string("ffmpeg failed to make ") + what + " " + output.string() +
                         " (exit status " + std::to_string(result.status) +
                         "): " + tail(result.errors));
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
