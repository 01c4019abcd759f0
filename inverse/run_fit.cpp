#include "inverse/run_fit.hpp"

#include "inverse/ceres_fit.hpp"
#include "inverse/conflicts.hpp"
#include "inverse/multistart.hpp"
#include "inverse/nlopt_fit.hpp"

#include <chrono>

namespace spifit::inverse {

FitResult run_fit(const FitProblem& problem, const FitRunOptions& options) {
  const std::string alg = options.algorithm.empty() ? problem.settings.algorithm : options.algorithm;
  const int starts = options.multistart > 0 ? options.multistart : problem.multistart;
  FitResult r = starts > 1 ? run_multistart(problem, options, starts)
                           : (is_nlopt_algorithm(alg) ? fit_with_nlopt(problem, options) : fit_with_ceres(problem, options));
  if (problem.per_experiment && r.usable) {
    const auto t0 = std::chrono::steady_clock::now();
    analyse_conflicts(problem, options, &r);
    r.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  if (problem.scene_runs) {
    r.scene_runs = problem.scene_runs->runs();
    r.failed_runs = problem.scene_runs->failures();
  }
  return r;
}

}  // namespace spifit::inverse
