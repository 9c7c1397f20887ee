#pragma once
/// \file
/// Progress of a run on a terminal: a bar redrawn in place, or plain lines every few seconds when
/// the stream is not a terminal (logs, CI).

#include <chrono>
#include <cstdio>

#include "lib/frame_stats.hpp"

namespace tissu {

class ProgressReporter {
 public:
  /// Reports to `stream`; as a bar if `interactive`.
  ProgressReporter(std::FILE* stream, bool interactive);
  /// Shows progress after `row`; the last frame ends the line.
  void operator()(const FrameStats& row);

 private:
  std::FILE* m_stream;
  bool m_interactive;
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point m_last_line{};
};

/// A reporter on stderr, interactive when stderr is a terminal.
ProgressReporter stderr_progress();

}  // namespace tissu
