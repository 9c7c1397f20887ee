#pragma once
/// \file
/// run.json, the record of a run in its folder: which tissu ran what, where, how long, and how it
/// ended. Written when the run ends, however it ends (completed, failed, stopped by a signal, or
/// an error such as a full disk). CGAL-free.

#include <filesystem>
#include <string>
#include <vector>

namespace tissu {

struct RunRecord {
  std::string scenario_file;           ///< as given on the command line
  std::vector<std::string> overrides;  ///< the --set assignments, in order
  std::string started_utc;             ///< ISO 8601, "2026-12-03T07:05:00Z"
  int threads = 0;                     ///< OpenMP threads the run used
  int frames = 0;                      ///< frames asked for, after frame 0
  int frames_done = 0;                 ///< frames completed, after frame 0
  /// "completed", "failed" (the simulation diverged), "stopped" (SIGINT or SIGTERM) or "error"
  /// (bad input found during setup, a file that could not be written)
  std::string status;
  int exit_status = 0;     ///< the program's exit status
  double wall_time_s = 0;  ///< from loading the scenario to the end (s)
  std::string message;     ///< the failure, stop or error line printed on stderr, or ""
};

/// The time now, ISO 8601 in UTC to the second.
std::string utc_now_text();

/// Writes `dir`/run.json: `record`, tissu's version and commit, and the machine (host name,
/// operating system, processor model, logical processors). Throws FileWriteError.
void write_run_record(const std::filesystem::path& dir, const RunRecord& record);

}  // namespace tissu
