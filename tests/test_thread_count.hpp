#pragma once
// The OpenMP thread count for the rest of a scope, restored at its end: tests that compare thread
// counts set it themselves, as the apps do, since the library sets no process state.

#include <omp.h>

namespace tissu::test {

class ScopedThreadCount {
 public:
  explicit ScopedThreadCount(int threads) : m_previous(omp_get_max_threads()) {
    omp_set_num_threads(threads);
  }
  ~ScopedThreadCount() { omp_set_num_threads(m_previous); }
  ScopedThreadCount(const ScopedThreadCount&) = delete;
  ScopedThreadCount& operator=(const ScopedThreadCount&) = delete;

 private:
  int m_previous;
};

}  // namespace tissu::test
