#pragma once
// Least-squares identification with Ceres (Levenberg-Marquardt or dogleg): exact derivatives
// through the material-point scenes (Jets), central differences for black boxes.
#include "inverse/fit/fit_result.hpp"

namespace spifit::inverse {

// Levenberg-Marquardt or dogleg (Ceres).
FitResult fit_with_ceres(const FitProblem& problem, const FitRunOptions& options = {});

}  // namespace spifit::inverse
