#include "lib/run_record.hpp"

#include <sys/utsname.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "lib/atomic_file.hpp"
#include "lib/version_info.hpp"

namespace tissu {
namespace {

/// The processor's "model name" from /proc/cpuinfo (Linux), or "unknown".
std::string processor_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
  }
  return "unknown";
}

nlohmann::json machine() {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  utsname system{};
  uname(&system);
  return {{"host", host},
          {"os", std::string(system.sysname) + " " + system.release + " " + system.machine},
          {"processor", processor_model()},
          {"logical_processors", std::thread::hardware_concurrency()}};
}

}  // namespace

std::string utc_now_text() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

void write_run_record(const std::filesystem::path& dir, const RunRecord& r) {
  const nlohmann::json record = {
      {"tissu_version", tissu_version()},
      {"commit", tissu_commit()},
      {"scenario_file", r.scenario_file},
      {"overrides", r.overrides},
      {"started_utc", r.started_utc},
      {"machine", machine()},
      {"threads", r.threads},
      {"frames", r.frames},
      {"frames_done", r.frames_done},
      {"status", r.status},
      {"exit_status", r.exit_status},
      {"wall_time_s", r.wall_time_s},
      {"message", r.message},
  };
  // replace: a path or an override may hold bytes that are not UTF-8
  write_file_atomically(dir / "run.json",
                        record.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n",
                        "run record");
}

}  // namespace tissu
