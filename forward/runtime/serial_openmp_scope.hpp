#pragma once
// Runs a library call without its own OpenMP parallel regions.
//
// Debian 12's CHOLMOD (SuiteSparse 5.12) opens an OpenMP region with a fixed 4 threads
// (CHOLMOD_OMP_NUM_THREADS, compiled in) for every supernode it assembles. On the 2-core test
// machine this oversubscribes the cores and turns each factorisation into thousands of thread
// wake-ups: the 45-degree cone pie of cone70_pie45_short spent 43 s in the linear solver with
// them and 19 s without (docs/design/decisions.md). While this scope lives, max-active-levels is 0, so
// every parallel region the calling thread opens runs on that thread alone; the element loops of
// spifit, outside the scope, keep all threads. Use it from serial code only (the ICV is global in
// libgomp).
//
// The scope also sets the calling thread's team size to 1: the OpenMP build of OpenBLAS
// (libopenblas0-openmp) sizes its own teams by omp_get_max_threads() and then waits for the
// partners of a split dgemm, which never come when max-active-levels is 0 -- a deadlock
// (docs/design/dependencies.md, BLAS).
#ifdef _OPENMP
#include <omp.h>
#endif

namespace spifit::runtime {

class SerialOpenMpScope {
 public:
  SerialOpenMpScope() {
#ifdef _OPENMP
    saved_levels_ = omp_get_max_active_levels();
    saved_threads_ = omp_get_max_threads();
    omp_set_max_active_levels(0);
    omp_set_num_threads(1);
#endif
  }
  ~SerialOpenMpScope() {
#ifdef _OPENMP
    omp_set_num_threads(saved_threads_);
    omp_set_max_active_levels(saved_levels_);
#endif
  }
  SerialOpenMpScope(const SerialOpenMpScope&) = delete;
  SerialOpenMpScope& operator=(const SerialOpenMpScope&) = delete;

 private:
  int saved_levels_ = 1, saved_threads_ = 1;
};

}  // namespace spifit::runtime
