#pragma once
/// \file
/// How many OpenMP threads a cloth is worth, for programs whose user chose none: no more than its
/// size pays for, and no more than the cores other processes leave idle.

#include <algorithm>
#include <optional>

namespace tissu {

/// Particles each thread should have at least: below, another thread costs the solver more than
/// it saves, since each parallel loop of a step wakes or waits for the other threads for a few
/// microseconds of work. On the hanging sheet (Newton, quasi-Newton), two threads were 2.5
/// times slower than one at 21 x 21 particles, 5 to 13 % slower at 41 x 41, 6 to 12 % faster at
/// 51 x 51 and 1.4 times faster at 81 x 81 (docs/benchmarks.md, "Threads by cloth size").
inline constexpr int min_particles_per_thread = 1250;

/// As many threads as give each min_particles_per_thread particles, at least one and at most
/// `available_threads` (the cores, or what the user allows).
inline int threads_for_particles(int particles, int available_threads) {
  return std::max(1, std::min(particles / min_particles_per_thread, available_threads));
}

/// Whether the user chose the thread count: the scenario's `threads` (> 0) or OMP_NUM_THREADS in
/// the environment. Programs choose it themselves (FrameThreadChooser) only when not.
bool user_chose_threads(int scenario_threads);

/// CPU time counters read at one instant.
struct CpuTimeSample {
  double wall_s = 0;          ///< monotonic clock
  double cores_busy_s = 0;    ///< time the cores this process may run on spent busy, all processes
  double this_process_s = 0;  ///< CPU time of this process, all its threads
  int cores = 0;              ///< cores in this process's affinity mask
};

/// The counters now: the busy time of the cores in this process's affinity mask from /proc/stat
/// (user, nice, system, irq, softirq and steal: steal is time a virtual machine's host gave to
/// others). nullopt where /proc/stat cannot be read (not Linux).
std::optional<CpuTimeSample> sample_cpu_times();

/// Cores' worth of CPU time other processes used between two samples:
/// (Δ cores_busy_s − Δ this_process_s) / Δ wall_s, at least 0.
double cores_used_by_others(const CpuTimeSample& earlier, const CpuTimeSample& later);

/// Threads of other processes ready to run at this instant: the fewest of `samples` readings of
/// /proc/stat's procs_running, `gap_s` apart, less the reading thread. The fewest, since one
/// reading may catch a short wake-up (or this process's OpenMP threads still spinning), while a
/// busy process is in every one. Counts the runnable threads of every core, not only this
/// process's: where its affinity mask leaves some out, it errs towards fewer threads. nullopt
/// where /proc/stat cannot be read.
std::optional<int> others_ready_to_run(int samples = 8, double gap_s = 0.25e-3);

/// Threads that do not share a core with the other processes' work: the cores left idle, rounded
/// to the nearest, at least 1. A busy process beside two threads of ours on two cores is measured
/// at about 2/3 of a core (three threads share two cores), which still leaves one thread.
int threads_beside_others(double others_cores, int cores);

/// Chooses the thread count at each frame of a run: threads_for_particles, capped by the cores
/// other processes left idle since the last choice (measured over at least `min_window_s`, so
/// that the 10 ms ticks of /proc/stat do not decide). An oversubscribed core makes every parallel
/// loop wait for its slowest thread: beside one busy process on two cores, two threads ran 7 to
/// 69 % slower than one (docs/benchmarks.md, "Threads beside a busy process").
///
/// Until its first window has passed, it counts the other processes' threads ready to run when it
/// is made (others_ready_to_run()), so that the first frames, whose first step from rest can be
/// the run's longest, are neither given threads unmeasured nor wait for a measurement: beside a
/// busy process, two threads for the first step made a 2.2 s run 1.5 times slower than one
/// thread, and waiting 0.1 s to measure made a one-frame run 0.07 s slower (docs/benchmarks.md,
/// "2026-12-07").
class FrameThreadChooser {
 public:
  explicit FrameThreadChooser(int available_threads, double min_window_s = 0.25);

  /// The threads for the next frame of a cloth of `particles` particles.
  int threads(int particles);

  /// The threads for work of any size (a cloth's set-up): the idle cores as last measured.
  int idle_threads() const { return std::min(m_available_threads, m_idle_cores); }

 private:
  int m_available_threads;
  double m_min_window_s;
  std::optional<CpuTimeSample> m_window_start;
  int m_idle_cores;  ///< as last measured; m_available_threads where nothing can be measured
};

/// The thread rule of the programs that run scenarios (`tissu run`, the Python module), in one
/// place: the scenario's `threads` where it sets them, OMP_NUM_THREADS where that is set;
/// otherwise the set-up on the cores other processes leave idle and each frame on as many as the
/// cloth's size also pays for (FrameThreadChooser). Sets the process's OpenMP threads.
class RunThreads {
 public:
  /// Starts measuring the other processes: make it before the scenario loads, so that the first
  /// measurement window starts early.
  RunThreads();

  /// Sets the threads for the set-up of a scenario whose `threads` is `scenario_threads`.
  void before_setup(int scenario_threads);

  /// Sets the threads for the next frame of a cloth of `particles` particles.
  void before_frame(int particles);

  /// The most threads a frame may run on: the scenario's threads, OMP_NUM_THREADS or the cores
  /// (valid after before_setup()).
  int most_threads() const { return m_most_threads; }

 private:
  FrameThreadChooser m_chooser;
  bool m_user_chose = false;
  int m_most_threads = 0;
};

}  // namespace tissu
