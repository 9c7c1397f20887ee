#include "lib/progress.hpp"

#include <unistd.h>

#include <string>

namespace tissu {

ProgressReporter::ProgressReporter(std::FILE* stream, bool interactive)
    : m_stream(stream), m_interactive(interactive) {}

ProgressReporter stderr_progress() {
  return ProgressReporter(stderr, isatty(STDERR_FILENO) == 1);
}

void ProgressReporter::operator()(const FrameStats& row) {
  using seconds = std::chrono::duration<double>;
  const auto now = std::chrono::steady_clock::now();
  const double wall_s = seconds(now - m_start).count();
  const double fraction = row.frame_count > 0 ? double(row.frame) / row.frame_count : 1.0;
  const double eta_s = fraction > 0 ? wall_s * (1.0 - fraction) / fraction : 0.0;
  const bool last = row.frame >= row.frame_count;
  if (m_interactive) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    const std::string bar = std::string(filled, '#') + std::string(width - filled, '-');
    std::fprintf(m_stream, "\r[%s] frame %d/%d  t = %.2f s  wall %.1f s  eta %.1f s  %d particles ",
                 bar.c_str(), row.frame, row.frame_count, row.time, wall_s, eta_s, row.particles);
    if (last) std::fputc('\n', m_stream);
    std::fflush(m_stream);
    return;
  }
  if (!last && row.frame != 0 && seconds(now - m_last_line).count() < 5.0) return;
  m_last_line = now;
  std::fprintf(m_stream, "frame %d/%d (%.0f%%)  t = %.2f s  wall %.1f s  eta %.1f s\n", row.frame,
               row.frame_count, 100.0 * fraction, row.time, wall_s, eta_s);
  std::fflush(m_stream);
}

}  // namespace tissu
