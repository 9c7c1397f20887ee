#include "apps/passive_openmp.hpp"

#include <unistd.h>

#include <cstdlib>

namespace tissu {

void prefer_passive_openmp_waiting(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: run on with the default policy
}

}  // namespace tissu
