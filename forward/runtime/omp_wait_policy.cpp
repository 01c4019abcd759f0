#include "forward/runtime/omp_wait_policy.hpp"

#include <cstdlib>
#include <unistd.h>

namespace spifit::runtime {

void ensure_passive_omp_wait(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (::setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  ::execv("/proc/self/exe", argv);  // returns only on failure
}

}  // namespace spifit::runtime
