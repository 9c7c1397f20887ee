#include "apps/openmp_waiting.hpp"

#include <unistd.h>

#include <cstdlib>

namespace tissu {

void prefer_short_openmp_spin(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("GOMP_SPINCOUNT", tissu_spin_count, 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: run on with the default policy
}

}  // namespace tissu
