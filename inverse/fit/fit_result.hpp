#pragma once
// The result of an identification, whatever the engine (Ceres, NLopt; docs/design/identification.md):
// the fitted values and card, costs, history, uncertainty, per-experiment fits and conflicts,
// multi-start spread; and the run options.
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_progress.hpp"
#include "inverse/uncertainty/uncertainty.hpp"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace spifit::inverse {

struct ExperimentCost {
  std::string name, kind;
  int points = 0;
  double cost = 0.0;  // 1/2 sum r^2 of this experiment at the solution
  double rms = 0.0;   // root-mean-square conditioned residual
  // With a stated noise: the rms of (simulated - measured) / noise over the points of nonzero
  // weight (the weights taken out), and how many those are; NaN and 0 without a stated noise.
  double noise_rms = std::numeric_limits<double>::quiet_NaN();
  int noise_points = 0;
  // Per free parameter: this experiment's share of its Fisher information at the solution
  // (information_shares in uncertainty.hpp; NaN where no experiment responds to it).
  std::vector<double> information_share;
};

struct FitResult {
  std::string algorithm, termination;
  unsigned seed = 0;  // NLopt seed (0 for the deterministic Ceres algorithms)
  bool usable = false;
  // Why the result is not usable as a card, in plain words (fit_assessment.hpp; run_fit fills it
  // and sets usable = false when it is not empty).
  std::vector<std::string> not_usable;
  std::vector<double> initial, values;  // physical values of the free parameters
  double cost_initial = 0.0, cost_final = 0.0;  // 1/2 sum of squared conditioned residuals
  int iterations = 0;
  long forward_runs = 0;
  double wall_seconds = 0.0;
  std::vector<double> cost_history;  // per iteration
  std::vector<ExperimentCost> experiment_costs;
  Uncertainty uncertainty;
  material::MaterialCard card;  // the fitted card
  // Optional: each experiment fitted alone from the global solution (conflicts.hpp).
  struct Alone {
    std::string experiment;
    bool usable = false;
    std::vector<double> values, ci95_lower, ci95_upper;
    std::vector<bool> identifiable;
  };
  std::vector<Alone> per_experiment;
  std::vector<std::string> conflicts;  // plain words: experiments that disagree on a parameter
  struct MultiStart {
    int starts = 1, best_start = 0, at_best = 0;
    struct Solution {
      bool usable = false;
      double cost = 0.0;
      std::vector<double> start, values;
    };
    std::vector<Solution> solutions;
    std::vector<double> spread_min, spread_max;  // over the starts that reached the best cost
  };
  MultiStart multistart;
  // FE experiments: the forward runs of their scenes (each parameter point once) and the runs
  // that failed or needed a retry (fit.json "failed_runs").
  long scene_runs = 0;
  std::vector<SceneRuns::Failure> failed_runs;
  // Forward runs and wall time per experiment (in fit order; run_fit fills them): evaluations
  // of its residuals, and for FE experiments the scene runs it asked for first and their summed
  // wall seconds; per FE scene file its runs (scene_file_runs).
  struct ExperimentRuns {
    std::string experiment;
    long evaluations = 0, scene_runs = 0;
    double run_seconds = 0.0;
  };
  std::vector<ExperimentRuns> experiment_runs;
  std::vector<SceneFileRuns> runs_by_scene;
};

struct FitRunOptions {
  std::string algorithm;  // overrides the fit file when not empty
  int threads = 1;        // parallel evaluation of experiments (Ceres num_threads)
  unsigned seed = 42;     // NLopt's stochastic algorithms and multi-start draws (in fit.json)
  int multistart = 0;     // overrides the fit file's multistart when > 0
  // Told of every iteration and FE forward run (null: nobody listens); run_fit configures it.
  std::shared_ptr<FitProgress> progress = nullptr;
};

}  // namespace spifit::inverse
