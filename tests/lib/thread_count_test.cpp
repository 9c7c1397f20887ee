// The thread count a cloth is worth grows with its particles, stays within what is available and
// leaves alone the cores other processes are using.

#include "lib/thread_count.hpp"

#include <gtest/gtest.h>
#include <omp.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace tissu {
namespace {

TEST(ThreadsForParticles, OneThreadPerBlockOfParticlesWithinTheAvailableThreads) {
  EXPECT_EQ(threads_for_particles(0, 2), 1);
  EXPECT_EQ(threads_for_particles(21 * 21, 2), 1);  // a small cloth: one thread
  EXPECT_EQ(threads_for_particles(41 * 41, 8), 1);
  EXPECT_EQ(threads_for_particles(2 * min_particles_per_thread - 1, 8), 1);
  EXPECT_EQ(threads_for_particles(2 * min_particles_per_thread, 8), 2);
  EXPECT_EQ(threads_for_particles(51 * 51, 2), 2);
  EXPECT_EQ(threads_for_particles(81 * 81, 2), 2);
  EXPECT_EQ(threads_for_particles(1000000, 2), 2);  // never more than the cores
  EXPECT_EQ(threads_for_particles(1000000, 1), 1);
  EXPECT_EQ(threads_for_particles(5000, 0), 1);
  EXPECT_EQ(threads_for_particles(10 * min_particles_per_thread, 4), 4);  // always at least one
}

TEST(UserChoseThreads, ByTheScenarioOrByOmpNumThreads) {
  const char* outer = std::getenv("OMP_NUM_THREADS");
  const std::optional<std::string> saved = outer ? std::optional<std::string>(outer) : std::nullopt;
  unsetenv("OMP_NUM_THREADS");
  EXPECT_FALSE(user_chose_threads(0));  // 0: the programs choose
  EXPECT_TRUE(user_chose_threads(1));
  EXPECT_TRUE(user_chose_threads(3));
  setenv("OMP_NUM_THREADS", "2", 1);
  EXPECT_TRUE(user_chose_threads(0));
  if (saved)
    setenv("OMP_NUM_THREADS", saved->c_str(), 1);
  else
    unsetenv("OMP_NUM_THREADS");
}

TEST(RunThreads, KeepTheThreadsTheUserChoseAndChooseThemOtherwise) {
  const char* outer = std::getenv("OMP_NUM_THREADS");
  const std::optional<std::string> saved = outer ? std::optional<std::string>(outer) : std::nullopt;
  const int outer_threads = omp_get_max_threads();
  unsetenv("OMP_NUM_THREADS");

  RunThreads by_scenario;
  by_scenario.before_setup(3);
  EXPECT_EQ(omp_get_max_threads(), 3);
  EXPECT_EQ(by_scenario.most_threads(), 3);
  by_scenario.before_frame(1000000);
  EXPECT_EQ(omp_get_max_threads(), 3);  // whatever the cloth's size

  RunThreads chosen;
  chosen.before_setup(0);
  EXPECT_EQ(chosen.most_threads(), omp_get_num_procs());
  EXPECT_GE(omp_get_max_threads(), 1);  // the idle cores
  EXPECT_LE(omp_get_max_threads(), omp_get_num_procs());
  chosen.before_frame(10);  // too few particles for a second thread
  EXPECT_EQ(omp_get_max_threads(), 1);

  setenv("OMP_NUM_THREADS", "2", 1);
  omp_set_num_threads(2);  // as the OpenMP runtime reads OMP_NUM_THREADS at start
  RunThreads by_environment;
  by_environment.before_setup(0);
  by_environment.before_frame(10);
  EXPECT_EQ(omp_get_max_threads(), 2);
  EXPECT_EQ(by_environment.most_threads(), 2);

  if (saved)
    setenv("OMP_NUM_THREADS", saved->c_str(), 1);
  else
    unsetenv("OMP_NUM_THREADS");
  omp_set_num_threads(outer_threads);
}

TEST(CoresUsedByOthers, IsTheBusyTimeNotSpentByThisProcessPerSecond) {
  const CpuTimeSample earlier{10.0, 100.0, 3.0, 2};
  EXPECT_DOUBLE_EQ(cores_used_by_others(earlier, {12.0, 103.0, 4.0, 2}), 1.0);
  EXPECT_DOUBLE_EQ(cores_used_by_others(earlier, {12.0, 102.0, 5.0, 2}), 0.0);  // all ours
  EXPECT_DOUBLE_EQ(cores_used_by_others(earlier, {12.0, 101.9, 5.0, 2}), 0.0);  // tick rounding
  EXPECT_DOUBLE_EQ(cores_used_by_others(earlier, earlier), 0.0);                // no time passed
}

TEST(ThreadsBesideOthers, LeaveTheCoresOtherProcessesUse) {
  EXPECT_EQ(threads_beside_others(0.0, 2), 2);
  EXPECT_EQ(threads_beside_others(0.3, 2), 2);   // a light load: two threads still pay
  EXPECT_EQ(threads_beside_others(0.67, 2), 1);  // one busy process sharing two cores with us
  EXPECT_EQ(threads_beside_others(1.0, 2), 1);
  EXPECT_EQ(threads_beside_others(1.0, 8), 7);
  EXPECT_EQ(threads_beside_others(5.0, 2), 1);  // never none
}

/// A child process that keeps one core busy until `seconds` have passed, then exits.
pid_t spin_in_child(double seconds) {
  const pid_t child = fork();
  if (child != 0) return child;
  timespec start{}, now{};
  clock_gettime(CLOCK_MONOTONIC, &start);
  do {
    clock_gettime(CLOCK_MONOTONIC, &now);
  } while (static_cast<double>(now.tv_sec - start.tv_sec) +
               1e-9 * static_cast<double>(now.tv_nsec - start.tv_nsec) <
           seconds);
  _exit(0);
}

TEST(FrameThreadChooser, LeavesACoreToABusyProcess) {
  const std::optional<CpuTimeSample> start = sample_cpu_times();
  ASSERT_TRUE(start.has_value()) << "/proc/stat unreadable: this test needs Linux";
  ASSERT_GE(start->cores, 1);
  FrameThreadChooser chooser(start->cores, 0.2);
  const pid_t child = spin_in_child(0.8);
  ASSERT_GT(child, 0);
  usleep(500 * 1000);  // this process sleeps: the busy time measured is the child's (and others')
  const std::optional<CpuTimeSample> end = sample_cpu_times();
  const int threads = chooser.threads(1000000);
  int child_status = 0;
  waitpid(child, &child_status, 0);

  ASSERT_TRUE(end.has_value());
  EXPECT_GE(cores_used_by_others(*start, *end), 0.7);
  EXPECT_LE(threads, std::max(1, start->cores - 1)) << "cores: " << start->cores;
}

TEST(FrameThreadChooser, CountsTheOtherProcessesReadyToRunBeforeItsFirstWindow) {
  const std::optional<CpuTimeSample> start = sample_cpu_times();
  ASSERT_TRUE(start.has_value()) << "/proc/stat unreadable: this test needs Linux";
  const pid_t child = spin_in_child(0.3);
  ASSERT_GT(child, 0);
  const std::optional<int> others = others_ready_to_run();
  // asked at once, its first window (10 s) far from over: it counts the busy child
  FrameThreadChooser chooser(start->cores, 10.0);
  const int threads = chooser.threads(1000000);
  int child_status = 0;
  waitpid(child, &child_status, 0);

  ASSERT_TRUE(others.has_value());
  EXPECT_GE(*others, 1);
  EXPECT_LE(threads, std::max(1, start->cores - 1)) << "cores: " << start->cores;
}

}  // namespace
}  // namespace tissu
