#include "inverse/fit/multistart.hpp"

#include "inverse/fit/ceres_fit.hpp"
#include "inverse/fit/fit_algorithms.hpp"
#include "inverse/fit/nlopt_fit.hpp"

#include <chrono>
#include <cmath>
#include <random>

namespace spifit::inverse {

FitResult run_multistart(const FitProblem& fp, const FitRunOptions& options, int starts) {
  const auto t0 = std::chrono::steady_clock::now();
  const ParameterSet& ps = *fp.parameters;
  const int p = ps.num_free();
  const auto lo = ps.lower_internal(), hi = ps.upper_internal();
  std::mt19937_64 rng(options.seed);
  auto uniform = [&] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };
  std::vector<FitResult> results;
  std::vector<std::vector<double>> start_points;
  for (int s = 0; s < starts; ++s) {
    std::vector<ParameterSpec> specs = ps.specs();
    std::vector<double> x0 = ps.initial_internal();
    if (s > 0) {
      for (int k = 0; k < p; ++k) x0[k] = lo[k] + uniform() * (hi[k] - lo[k]);
    }
    for (int k = 0; k < p; ++k) specs[ps.free_indices()[k]].initial = ps.to_physical(k, x0[k]);
    FitProblem one;
    one.name = fp.name;
    one.file = fp.file;
    one.parameters = std::make_unique<ParameterSet>(ps.base(), specs, ps.normalise_hill());
    one.experiments = fp.experiments;
    one.settings = fp.settings;
    FitRunOptions o = options;
    if (o.progress) o.progress->set_phase("start " + std::to_string(s + 1) + " of " + std::to_string(starts));
    results.push_back(is_nlopt_algorithm(o.algorithm.empty() ? fp.settings.algorithm : o.algorithm) ? fit_with_nlopt(one, o)
                                                                                                     : fit_with_ceres(one, o));
    start_points.push_back(x0);
  }
  int best = -1;
  for (int s = 0; s < starts; ++s) {
    if (results[s].usable && (best < 0 || results[s].cost_final < results[best].cost_final)) best = s;
  }
  FitResult out = results[best < 0 ? 0 : best];
  out.multistart.starts = starts;
  out.multistart.best_start = best;
  long runs = 0;
  for (int s = 0; s < starts; ++s) {
    const auto& r = results[s];
    runs += r.forward_runs;
    FitResult::MultiStart::Solution sol;
    sol.usable = r.usable;
    sol.cost = r.cost_final;
    for (int k = 0; k < p; ++k) sol.start.push_back(ps.to_physical(k, start_points[s][k]));
    sol.values = r.values;
    out.multistart.solutions.push_back(sol);
  }
  // Spread over the solutions that reached the best cost (relative 1e-6): a unique optimum
  // gives a spread at the level of the optimiser's tolerance.
  if (best >= 0) {
    const double c = results[best].cost_final;
    out.multistart.spread_min.assign(p, INFINITY);
    out.multistart.spread_max.assign(p, -INFINITY);
    for (const auto& r : results) {
      if (!r.usable || r.cost_final > c * (1.0 + 1e-6) + 1e-12) continue;
      ++out.multistart.at_best;
      for (int k = 0; k < p; ++k) {
        out.multistart.spread_min[k] = std::min(out.multistart.spread_min[k], r.values[k]);
        out.multistart.spread_max[k] = std::max(out.multistart.spread_max[k], r.values[k]);
      }
    }
    if (out.multistart.at_best < starts) {
      out.uncertainty.warnings.push_back(std::to_string(starts - out.multistart.at_best) + " of " + std::to_string(starts) +
                                         " starts ended in a different (worse) minimum or failed; the best one is reported.");
    }
  }
  out.forward_runs = runs;
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace spifit::inverse
