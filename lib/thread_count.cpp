#include "lib/thread_count.hpp"

#include <omp.h>
#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace tissu {
namespace {

double seconds(clockid_t clock) {
  timespec now{};
  clock_gettime(clock, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// Busy ticks of one "cpuN user nice system idle iowait irq softirq steal ..." line of
/// /proc/stat, whose fields after the name are in USER_HZ ticks (proc(5)).
long long busy_ticks(std::istringstream& fields) {
  long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  fields >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
  return user + nice + system + irq + softirq + steal;
}

}  // namespace

bool user_chose_threads(int scenario_threads) {
  return scenario_threads > 0 || std::getenv("OMP_NUM_THREADS") != nullptr;
}

std::optional<CpuTimeSample> sample_cpu_times() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof(allowed), &allowed) != 0) return std::nullopt;
  std::ifstream stat("/proc/stat");
  if (!stat) return std::nullopt;
  const double seconds_per_tick = 1.0 / static_cast<double>(sysconf(_SC_CLK_TCK));

  CpuTimeSample sample;
  sample.wall_s = seconds(CLOCK_MONOTONIC);
  sample.this_process_s = seconds(CLOCK_PROCESS_CPUTIME_ID);
  std::string line;
  while (std::getline(stat, line)) {
    // per-core lines only: "cpu0 ...", not the "cpu ..." total of every core
    if (line.size() < 4 || line.compare(0, 3, "cpu") != 0 || line[3] == ' ') continue;
    std::istringstream fields(line.substr(3));
    int core = -1;
    fields >> core;
    if (!fields || core < 0 || core >= CPU_SETSIZE || !CPU_ISSET(core, &allowed)) continue;
    sample.cores_busy_s += static_cast<double>(busy_ticks(fields)) * seconds_per_tick;
    ++sample.cores;
  }
  if (sample.cores == 0) return std::nullopt;
  return sample;
}

double cores_used_by_others(const CpuTimeSample& earlier, const CpuTimeSample& later) {
  const double wall_s = later.wall_s - earlier.wall_s;
  if (!(wall_s > 0)) return 0;
  const double others_s =
      (later.cores_busy_s - earlier.cores_busy_s) - (later.this_process_s - earlier.this_process_s);
  return std::max(0.0, others_s / wall_s);
}

int threads_beside_others(double others_cores, int cores) {
  return std::max(1, static_cast<int>(std::lround(static_cast<double>(cores) - others_cores)));
}

std::optional<int> others_ready_to_run(int samples, double gap_s) {
  std::optional<int> fewest;
  for (int k = 0; k < samples; ++k) {
    if (k > 0) std::this_thread::sleep_for(std::chrono::duration<double>(gap_s));
    std::ifstream stat("/proc/stat");
    std::string name;
    int running = 0;
    while (stat >> name && name != "procs_running") stat.ignore(1 << 20, '\n');
    if (!(stat >> running)) return std::nullopt;
    fewest = std::min(fewest.value_or(running), running);
  }
  if (!fewest) return std::nullopt;
  return std::max(0, *fewest - 1);  // the reading thread is running
}

FrameThreadChooser::FrameThreadChooser(int available_threads, double min_window_s)
    : m_available_threads(std::max(1, available_threads)),
      m_min_window_s(min_window_s),
      m_window_start(sample_cpu_times()),
      m_idle_cores(m_available_threads) {
  const std::optional<int> others = others_ready_to_run();
  if (m_window_start && others)
    m_idle_cores = threads_beside_others(*others, m_window_start->cores);
}

int FrameThreadChooser::threads(int particles) {
  const int wanted = threads_for_particles(particles, m_available_threads);
  if (m_window_start) {
    const std::optional<CpuTimeSample> now = sample_cpu_times();
    if (now && now->wall_s - m_window_start->wall_s >= m_min_window_s) {
      m_idle_cores = threads_beside_others(cores_used_by_others(*m_window_start, *now), now->cores);
      m_window_start = now;
    }
  }
  return std::min(wanted, m_idle_cores);
}

// the cores (omp_get_num_procs(), not omp_get_max_threads(): an earlier run's choice in the same
// process may have lowered that)
RunThreads::RunThreads() : m_chooser(omp_get_num_procs()) {}

void RunThreads::before_setup(int scenario_threads) {
  if (scenario_threads > 0) omp_set_num_threads(scenario_threads);
  m_user_chose = user_chose_threads(scenario_threads);
  m_most_threads = m_user_chose ? omp_get_max_threads() : omp_get_num_procs();
  if (!m_user_chose) omp_set_num_threads(m_chooser.idle_threads());
}

void RunThreads::before_frame(int particles) {
  if (!m_user_chose) omp_set_num_threads(m_chooser.threads(particles));
}

}  // namespace tissu
