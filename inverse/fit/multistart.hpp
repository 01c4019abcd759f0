#pragma once
// Multi-start (docs/design/identification.md): the fit from its own initial point plus starts drawn uniformly
// (seeded, in internal coordinates: uniform in ln(value) for log-scaled parameters) inside the
// bounds; the best solution is returned, and the spread of the solutions says whether the
// optimum is unique.
#include "inverse/fit/fit_result.hpp"

namespace spifit::inverse {

FitResult run_multistart(const FitProblem& problem, const FitRunOptions& options, int starts);

}  // namespace spifit::inverse
