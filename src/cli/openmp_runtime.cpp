// The OpenMP threads' spin before sleeping (see openmp_runtime.hpp).
#include "cli/openmp_runtime.hpp"

#include <unistd.h>

#include <cstdlib>

namespace mistfall {

void useShortOpenMpSpin(char** argv) {
  if (std::getenv("GOMP_SPINCOUNT") || std::getenv("OMP_WAIT_POLICY")) return;
  if (setenv("GOMP_SPINCOUNT", "1000", 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure
  unsetenv("GOMP_SPINCOUNT");
}

}  // namespace mistfall
