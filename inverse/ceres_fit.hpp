#pragma once
// Least-squares identification with Ceres (Levenberg-Marquardt or dogleg), exact derivatives
// through the material-point scenes (Jets), uncertainty at the solution.
#include "inverse/fit_file.hpp"
#include "inverse/uncertainty.hpp"

#include <string>
#include <vector>

namespace spifit::inverse {

struct ExperimentCost {
  std::string name, kind;
  int points = 0;
  double cost = 0.0;  // 1/2 sum r^2 of this experiment at the solution
  double rms = 0.0;   // root-mean-square conditioned residual
};

struct FitResult {
  std::string algorithm, termination;
  unsigned seed = 0;  // NLopt seed (0 for the deterministic Ceres algorithms)
  bool usable = false;
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
};

struct FitRunOptions {
  std::string algorithm;  // overrides the fit file when not empty
  int threads = 1;        // parallel evaluation of experiments (Ceres num_threads)
  unsigned seed = 42;     // NLopt's stochastic algorithms and multi-start draws (in fit.json)
  int multistart = 0;     // overrides the fit file's multistart when > 0
};

// Levenberg-Marquardt or dogleg (Ceres).
FitResult fit_with_ceres(const FitProblem& problem, const FitRunOptions& options = {});
// Dispatches on the algorithm: Ceres names or NLopt names (nlopt_fit.hpp).
FitResult run_fit(const FitProblem& problem, const FitRunOptions& options = {});

// Fills values, card, Jacobian-based uncertainty and per-experiment costs at the internal
// point x (shared by the Ceres and NLopt drivers).
void analyse_solution(const FitProblem& problem, const std::vector<double>& x, int threads, FitResult* out);

// Cost and conditioned residuals at an internal parameter vector (false: a forward run failed).
bool evaluate_residuals(const FitProblem& problem, const std::vector<double>& internal, Eigen::VectorXd* residuals);

}  // namespace spifit::inverse
