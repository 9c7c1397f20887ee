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
  /// Shows simulation progress after `row`; the last frame ends the line.
  void operator()(const FrameStats& row);
  /// Shows rendering progress after `done` of `total` images; the last ends the line.
  void rendered(int done, int total);

 private:
  std::FILE* m_stream;
  bool m_interactive;
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point m_last_line{};
  std::chrono::steady_clock::time_point m_render_start{};

  /// One progress line: "[bar] <what>  wall ..  eta .." or a plain line every 5 s.
  void show(double fraction, bool last, const char* what, double elapsed_s);
};

/// A reporter on stderr, interactive when stderr is a terminal.
ProgressReporter stderr_progress();

}  // namespace tissu
