// Time of the bundled AA3003-O identification (goal: fit Hill + Swift to 3 tensile + 1
// shear curve in < 1 s on 2 cores, docs/results/benchmarks.md, "Material points and fit_classic"), with
// its iterations, forward runs and the largest relative deviation of the fitted values from
// the generating card C.2 (data are synthetic); without and with the per-experiment conflict
// check that fit files of material points run by default (each experiment fitted alone after).
#include "inverse/fit/run_fit.hpp"
#include "bench/fit_runs.hpp"
#include "inverse/fit/fit_file.hpp"

#include <benchmark/benchmark.h>

using namespace spifit;

static void fit_classic(benchmark::State& state) {
  auto fp = inverse::read_fit_file(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/fit_classic.toml");
  fp.per_experiment = state.range(1) != 0;
  const auto truth = material::load_material_card(std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c2.toml");
  inverse::FitRunOptions o;
  o.threads = static_cast<int>(state.range(0));
  const inverse::FitResult r = bench::run_fit_each_iteration(state, fp, o);
  const double dev = bench::largest_relative_deviation(fp, r, [&](const inverse::ParameterSpec& s) { return inverse::parameter_value(truth, s.name); });
  state.counters["iterations"] = r.iterations;
  state.counters["forward_runs"] = static_cast<double>(r.forward_runs);
  state.counters["max_rel_dev_from_C2"] = dev;
}
// Arguments: threads, conflict check (0: off, 1: on).
BENCHMARK(fit_classic)->Args({1, 0})->Args({2, 0})->Args({1, 1})->Args({2, 1})->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
