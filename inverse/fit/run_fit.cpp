#include "inverse/fit/run_fit.hpp"

#include "inverse/fit/ceres_fit.hpp"
#include "inverse/fit/conflicts.hpp"
#include "inverse/fit/fit_assessment.hpp"
#include "inverse/fit/multistart.hpp"
#include "inverse/fit/fit_algorithms.hpp"
#include "inverse/fit/nlopt_fit.hpp"

#include <algorithm>
#include <chrono>
#include <set>

namespace spifit::inverse {
namespace {

// The FE forward runs one iteration asks: per FE scene file of the experiments, the point and,
// unless derivative_free (NLopt) or its experiments take exact derivatives from that run, its 2p
// central-difference neighbours.
long fe_runs_per_iteration(const std::vector<std::shared_ptr<Experiment>>& experiments, int free_parameters, bool derivative_free) {
  std::set<std::string> files, exact;
  for (const auto& e : experiments) {
    if (e->scene_file().empty()) continue;
    files.insert(e->scene_file());
    if (e->exact_columns() > 0) exact.insert(e->scene_file());
  }
  long runs = 0;
  for (const auto& f : files) runs += derivative_free || exact.count(f) ? 1 : 1 + 2L * free_parameters;
  return runs;
}

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

// What an iteration asks of the FE scenes: the point and, for Ceres, its 2p central-difference
// neighbours per scene file (NLopt's iterations are single evaluations), run `width` at a time
// (threads, or an MPI job's workers).
void configure_progress(const FitProblem& problem, const FitRunOptions& options, const std::string& algorithm) {
  if (!options.progress) return;
  int width = std::max(1, options.threads);
  for (const auto& e : problem.experiments) width = std::max(width, e->parallel_evaluations());
  options.progress->configure(fe_runs_per_iteration(problem.experiments, problem.parameters->num_free(), is_nlopt_algorithm(algorithm)), width);
  if (problem.scene_runs) problem.scene_runs->on_run([progress = options.progress](double s) { progress->run_finished(s); });
}

}  // namespace

FitResult run_fit(const FitProblem& problem, const FitRunOptions& options) {
  const std::string alg = options.algorithm.empty() ? problem.settings.algorithm : options.algorithm;
  configure_progress(problem, options, alg);
  const int starts = options.multistart > 0 ? options.multistart : problem.multistart;
  FitResult r = starts > 1 ? run_multistart(problem, options, starts)
                           : (is_nlopt_algorithm(alg) ? fit_with_nlopt(problem, options) : fit_with_ceres(problem, options));
  if (problem.per_experiment && r.usable) {
    const auto t0 = std::chrono::steady_clock::now();
    analyse_conflicts(problem, options, &r);
    if (options.progress) {
      options.progress->set_phase("");
      options.progress->set_runs_per_iteration(fe_runs_per_iteration(problem.experiments, problem.parameters->num_free(), false));
    }
    r.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  record_runs(problem, &r);
  r.not_usable = unusable_reasons(problem, r);
  if (!r.not_usable.empty()) r.usable = false;
  return r;
}

}  // namespace spifit::inverse
