// Fits on FE scenes (docs/design/identification.md, "Fits on FE scenes"):
// - fe_jacobian_steps: the noise of the central-difference Jacobian of an FE experiment (the
//   indent test's Fz against depth of fit_af_indent) for relative steps 1e-7 ... 1e-2, as the
//   relative distance of each column from the column at step 1e-3; the step rule of
//   numeric_cost.hpp must sit where this is flat.
// - fit_fe: the bundled FE fits end to end, three times each (median, min): wall time,
//   iterations, scene runs and the largest relative deviation of the fitted values from the
//   generating card or friction.
#include "bench/fit_runs.hpp"
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/run_fit.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace spifit;

namespace {

std::string src(const std::string& rel) { return std::string(SPIFIT_SOURCE_DIR) + "/" + rel; }

// Central difference of the experiment's residuals along free parameter k (internal coordinates).
Eigen::VectorXd column(const inverse::FitProblem& fp, const inverse::Experiment& e, int k, double rel) {
  const auto& ps = *fp.parameters;
  const auto x0 = ps.initial_internal();
  const auto lo = ps.lower_internal(), hi = ps.upper_internal();
  const double h = rel * std::max(std::abs(x0[static_cast<std::size_t>(k)]), 1e-3 * (hi[k] - lo[k]));
  Eigen::VectorXd rp(e.num_residuals()), rm(e.num_residuals());
  bool ok[2] = {false, false};
#pragma omp parallel for num_threads(2)
  for (int side = 0; side < 2; ++side) {
    auto x = x0;
    x[static_cast<std::size_t>(k)] += side == 0 ? h : -h;
    ok[side] = e.residuals(ps.point(x.data()), side == 0 ? rp.data() : rm.data());
  }
  if (!ok[0] || !ok[1]) return Eigen::VectorXd::Constant(e.num_residuals(), std::nan(""));
  return (rp - rm) / (2.0 * h);
}

void fe_jacobian_steps(benchmark::State& state) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/fit_af_indent.toml"));
  const inverse::Experiment* e = nullptr;
  for (const auto& x : fp.experiments)
    if (!x->supports_jets()) e = x.get();
  const auto& ps = *fp.parameters;
  const double steps[] = {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2};
  for (auto _ : state) {
    for (int k = 0; k < ps.num_free(); ++k) {
      std::vector<Eigen::VectorXd> cols;
      for (double rel : steps) cols.push_back(column(fp, *e, k, rel));
      // Against h = 1e-3 (truncation grows with h) and against h = 1e-5 (the noise of small steps).
      const std::string name = ps.specs()[ps.free_indices()[k]].name;
      for (const std::size_t r : {std::size_t{4}, std::size_t{2}}) {
        const Eigen::VectorXd& ref = cols[r];
        std::printf("%-12s |d/dx| %10.4g, against h=%.0e:", name.c_str(), ref.norm(), steps[r]);
        for (std::size_t i = 0; i < cols.size(); ++i) {
          const double err = (cols[i] - ref).norm() / ref.norm();
          std::printf("  h=%.0e %.2e", steps[i], err);
          if (r == 4) state.counters[name + " h=" + std::to_string(static_cast<int>(std::log10(steps[i])))] = err;
        }
        std::printf("\n");
      }
    }
  }
}
BENCHMARK(fe_jacobian_steps)->Unit(benchmark::kSecond)->Iterations(1);

// Fitted values against the truth: the generating card's or, for scene inputs, `truth`.
void fit_fe(benchmark::State& state, const std::string& fit, const std::string& card, double truth) {
  const auto fp = inverse::read_fit_file(src("experiments/aa3003o/" + fit));
  const auto generating = material::load_material_card(src("materials/" + card));
  inverse::FitRunOptions o;
  o.threads = 2;
  const inverse::FitResult r = bench::run_fit_each_iteration(state, fp, o);
  const double dev = bench::largest_relative_deviation(
      fp, r, [&](const inverse::ParameterSpec& s) { return s.scene_input ? truth : inverse::parameter_value(generating, s.name); });
  state.counters["iterations"] = r.iterations;
  state.counters["scene_runs"] = static_cast<double>(r.scene_runs);
  state.counters["failed_runs"] = static_cast<double>(r.failed_runs.size());
  state.counters["max_rel_dev"] = dev;
  state.counters["usable"] = r.usable;
}
// One fit per repetition, three repetitions: the median is the number docs/results/benchmarks.md quotes.
#define SPIFIT_FE_FIT(name, card, truth)                                                  \
  BENCHMARK_CAPTURE(fit_fe, name, #name ".toml", card, truth)                              \
      ->Unit(benchmark::kSecond)                                                          \
      ->Iterations(1)                                                                     \
      ->Repetitions(3)                                                                    \
      ->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
SPIFIT_FE_FIT(fit_af_indent, "aa3003o_c7n_af_shell.toml", 0.0);
SPIFIT_FE_FIT(fit_ziegler_indent, "aa3003o_c8_ziegler_shell.toml", 0.0);
SPIFIT_FE_FIT(fit_cone_friction, "aa3003o_c3c4.toml", 0.05);
SPIFIT_FE_FIT(fit_friction_line, "aa3003o_c3c4.toml", 0.1);
SPIFIT_FE_FIT(fit_section_line, "aa3003o_c3c4.toml", 0.0);
#undef SPIFIT_FE_FIT

}  // namespace

BENCHMARK_MAIN();
