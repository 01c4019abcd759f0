#pragma once
// Do the experiments agree? Each experiment is fitted alone (from the global solution, same
// free parameters); where two experiments both determine a parameter and their 95 % intervals
// do not overlap, they disagree on it (docs/reference/file-formats.md: the r45 and shear tests disagree on N, cards C.2 and C.3).
#include "inverse/fit/fit_result.hpp"

namespace spifit::inverse {

void analyse_conflicts(const FitProblem& problem, const FitRunOptions& options, FitResult* result);

}  // namespace spifit::inverse
