#pragma once
// An identification from a fit file with the engine its algorithm names (Ceres:
// levenberg_marquardt, dogleg; NLopt: the others), multi-start and the per-experiment fits when
// asked; and what every engine does at its solution (solution_analysis.hpp).
#include "inverse/fit_result.hpp"

namespace spifit::inverse {

// Dispatches on the algorithm: Ceres names or NLopt names (nlopt_fit.hpp).
FitResult run_fit(const FitProblem& problem, const FitRunOptions& options = {});

// The FE forward runs one iteration asks (FitProgress): per FE scene file of the experiments, the
// point and, unless derivative_free (NLopt), its 2p central-difference neighbours.
long fe_runs_per_iteration(const std::vector<std::shared_ptr<Experiment>>& experiments, int free_parameters, bool derivative_free);

}  // namespace spifit::inverse
