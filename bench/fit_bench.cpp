// Time of the bundled AA3003-O identification (goal: fit Hill + Swift to 3 tensile + 1
// shear curve in < 1 s on 2 cores, docs/benchmarks.md, "Identification: fit_classic"), with
// its iterations, forward runs and the largest relative deviation of the fitted values from
// the generating card C.2 (data are synthetic); without and with the per-experiment conflict
// check that fit files of material points run by default (each experiment fitted alone after).
#include "inverse/run_fit.hpp"
#include "inverse/fit_file.hpp"

#include <benchmark/benchmark.h>

using namespace spifit;

static void fit_classic(benchmark::State& state) {
  auto fp = inverse::read_fit_file(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/fit_classic.toml");
  fp.per_experiment = state.range(1) != 0;
  const auto truth = material::load_material_card(std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c2.toml");
  inverse::FitRunOptions o;
  o.threads = static_cast<int>(state.range(0));
  inverse::FitResult r;
  for (auto _ : state) {
    r = inverse::run_fit(fp, o);
    benchmark::DoNotOptimize(r.values.data());
  }
  double dev = 0.0;
  for (int k = 0; k < fp.parameters->num_free(); ++k) {
    const auto& name = fp.parameters->specs()[fp.parameters->free_indices()[k]].name;
    dev = std::max(dev, std::abs(r.values[k] / inverse::parameter_value(truth, name) - 1.0));
  }
  state.counters["iterations"] = r.iterations;
  state.counters["forward_runs"] = static_cast<double>(r.forward_runs);
  state.counters["max_rel_dev_from_C2"] = dev;
}
// Arguments: threads, conflict check (0: off, 1: on).
BENCHMARK(fit_classic)->Args({1, 0})->Args({2, 0})->Args({1, 1})->Args({2, 1})->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
