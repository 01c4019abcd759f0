#include "inverse/run_fit.hpp"

#include "inverse/ceres_fit.hpp"
#include "inverse/conflicts.hpp"
#include "inverse/multistart.hpp"
#include "inverse/nlopt_fit.hpp"

#include <chrono>

namespace spifit::inverse {
namespace {

// The forward runs of the fit: per experiment and, with FE experiments, per scene file.
void record_runs(const FitProblem& problem, FitResult* r) {
  std::vector<SceneRuns::Run> log;
  if (problem.scene_runs) {
    r->scene_runs = problem.scene_runs->runs();
    r->failed_runs = problem.scene_runs->failures();
    log = problem.scene_runs->run_log();
    r->runs_by_scene = scene_file_runs(log, r->failed_runs);
  }
  r->experiment_runs.clear();
  for (const auto& e : problem.experiments) {
    FitResult::ExperimentRuns x{e->name(), e->evaluations(), 0, 0.0};
    for (const auto& run : log) {
      if (run.experiment != e->name()) continue;
      ++x.scene_runs;
      x.run_seconds += run.seconds;
    }
    r->experiment_runs.push_back(x);
  }
}

}  // namespace

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
  record_runs(problem, &r);
  return r;
}

}  // namespace spifit::inverse
