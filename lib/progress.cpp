#include "lib/progress.hpp"

#include <unistd.h>

#include <string>

namespace tissu {
namespace {

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

ProgressReporter::ProgressReporter(std::FILE* stream, bool interactive)
    : m_stream(stream), m_interactive(interactive) {}

ProgressReporter stderr_progress() {
  return ProgressReporter(stderr, isatty(STDERR_FILENO) == 1);
}

void ProgressReporter::show(double fraction, bool last, const char* what, double elapsed_s) {
  const auto now = std::chrono::steady_clock::now();
  const double eta_s = fraction > 0 ? elapsed_s * (1.0 - fraction) / fraction : 0.0;
  if (m_interactive) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    const std::string bar = std::string(filled, '#') + std::string(width - filled, '-');
    std::fprintf(m_stream, "\r[%s] %s  wall %.1f s  eta %.1f s ", bar.c_str(), what, elapsed_s,
                 eta_s);
    if (last) std::fputc('\n', m_stream);
  } else if (last || fraction == 0.0 || seconds_between(m_last_line, now) >= 5.0) {
    m_last_line = now;
    std::fprintf(m_stream, "%s (%.0f%%)  wall %.1f s  eta %.1f s\n", what, 100.0 * fraction,
                 elapsed_s, eta_s);
  }
  std::fflush(m_stream);
}

void ProgressReporter::operator()(const FrameStats& row) {
  const double fraction = row.frame_count > 0 ? double(row.frame) / row.frame_count : 1.0;
  char what[128];
  std::snprintf(what, sizeof what, "frame %d/%d  t = %.2f s  %d particles", row.frame,
                row.frame_count, row.time, row.particles);
  show(fraction, row.frame >= row.frame_count, what,
       seconds_between(m_start, std::chrono::steady_clock::now()));
}

void ProgressReporter::rendered(int done, int total) {
  const auto now = std::chrono::steady_clock::now();
  if (done <= 1) m_render_start = now;
  char what[64];
  std::snprintf(what, sizeof what, "rendered %d/%d images", done, total);
  show(double(done) / total, done >= total, what, seconds_between(m_render_start, now));
}

}  // namespace tissu
