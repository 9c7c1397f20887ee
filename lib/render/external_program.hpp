#pragma once
/// \file
/// Running a helper program (ffmpeg, gnuplot) found on the PATH, without a shell.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/stop_request.hpp"

namespace tissu {

struct ProgramResult {
  int status = -1;       ///< exit status, or -1 if it did not start or was killed
  std::string errors;    ///< what it wrote on stderr
  bool stopped = false;  ///< ended by tissu because a stop was requested
};

/// The first executable `name` in the directories of $PATH.
std::optional<std::filesystem::path> find_on_path(const std::string& name);

/// Runs `program` with `arguments`, stdin and stdout on /dev/null, collecting stderr. When `stop`
/// is requested while it runs (checked every 0.1 s), sends it SIGTERM, waits for it to end and
/// returns with stopped = true.
ProgramResult run_program(const std::filesystem::path& program,
                          const std::vector<std::string>& arguments, StopRequest stop = {});

/// The last 300 characters of `text` on one line ("no error output" when empty), for messages.
std::string last_output(const std::string& text);

}  // namespace tissu
