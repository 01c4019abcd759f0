#include "forward/runtime/blas_threads.hpp"

#include <dlfcn.h>

#include <mutex>

namespace spifit::runtime {

namespace {

// openblas_get_parallel(): 0 sequential, 1 pthreads, 2 OpenMP; -1 when not OpenBLAS.
int openblas_parallel() {
  static std::once_flag once;
  static int kind = -1;
  std::call_once(once, [] {
    using GetParallel = int (*)();
    using SetThreads = void (*)(int);
    const auto get = reinterpret_cast<GetParallel>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
    if (!get) return;
    kind = get();
    if (kind == 1)
      if (const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
  });
  return kind;
}

}  // namespace

bool blas_allows_concurrent_calls() { return openblas_parallel() != 0; }

const char* blas_description() {
  switch (openblas_parallel()) {
    case 0: return "OpenBLAS (serial)";
    case 1: return "OpenBLAS (pthreads)";
    case 2: return "OpenBLAS (OpenMP)";
    default: return "not OpenBLAS";
  }
}

}  // namespace spifit::runtime
