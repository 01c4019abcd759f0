#pragma once
// An identification from a fit file with the engine its algorithm names (Ceres:
// levenberg_marquardt, dogleg; NLopt: the others), multi-start and the per-experiment fits when
// asked; and what every engine does at its solution (solution_analysis.hpp).
#include "inverse/fit/fit_result.hpp"

namespace spifit::inverse {

// Dispatches on the algorithm: Ceres names or NLopt names (nlopt_fit.hpp).
FitResult run_fit(const FitProblem& problem, const FitRunOptions& options = {});

}  // namespace spifit::inverse
