#pragma once
// The tail of every benchmark program's main(): Google Benchmark's flags, the run, the exit
// code (1 for an unknown flag). Benchmarks are registered before.
#include <benchmark/benchmark.h>

namespace spifit::bench {

inline int run_registered_benchmarks(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace spifit::bench
