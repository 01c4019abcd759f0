#pragma once
// Derivative-free and global identification with NLopt (docs/design/identification.md): local BOBYQA, COBYLA,
// Nelder-Mead, Sbplx; global DIRECT-L, CRS2, ISRES, MLSL (with BOBYQA as local optimiser).
// The objective is the same cost as Ceres's (1/2 sum of squared conditioned residuals); a
// failed forward run costs kFailedRunCost (finite, never NaN). The best point seen is kept
// and returned even when NLopt stops on round-off.
#include "inverse/fit/fit_result.hpp"

namespace spifit::inverse {

constexpr double kFailedRunCost = 1e30;

FitResult fit_with_nlopt(const FitProblem& problem, const FitRunOptions& options);

}  // namespace spifit::inverse
