#pragma once
/// \file
/// A request to stop a long operation early (a run, a rendering, a video), made from outside it:
/// typically a flag a SIGINT or SIGTERM handler sets (apps/stop_signals.hpp). The library never
/// installs handlers or reads globals itself; the program hands it the flag. Operations check it
/// between units of work (a solver step, a frame, an image) and stop with every file they have
/// written complete. Header only, CGAL-free.

#include <csignal>

namespace tissu {

struct StopRequest {
  /// nonzero once a stop is asked for (e.g. the signal number); none: never stop
  const volatile std::sig_atomic_t* flag = nullptr;

  bool requested() const { return flag != nullptr && *flag != 0; }
};

}  // namespace tissu
