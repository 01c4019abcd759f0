#pragma once
// Shared by the fit benchmarks (bench_fit, bench_fe_fit): run a fit once per benchmark iteration
// and measure how far its values lie from the values the data were generated with.
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/run_fit.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace spifit::bench {

// The result of the last of the benchmark's iterations, each one whole fit.
inline inverse::FitResult run_fit_each_iteration(benchmark::State& state, const inverse::FitProblem& fp, const inverse::FitRunOptions& o) {
  inverse::FitResult r;
  for (auto _ : state) {
    r = inverse::run_fit(fp, o);
    benchmark::DoNotOptimize(r.values.data());
  }
  return r;
}

// The largest |value / truth - 1| over the free parameters; truth(spec) gives each one's truth.
inline double largest_relative_deviation(const inverse::FitProblem& fp, const inverse::FitResult& r,
                                         const std::function<double(const inverse::ParameterSpec&)>& truth) {
  double dev = 0.0;
  for (int k = 0; k < fp.parameters->num_free(); ++k) {
    const auto& s = fp.parameters->specs()[fp.parameters->free_indices()[k]];
    dev = std::max(dev, std::abs(r.values[k] / truth(s) - 1.0));
  }
  return dev;
}

}  // namespace spifit::bench
