#pragma once
// Whether a fit's result can be used as a material card (docs/design/identification.md, "When a
// fit is usable"). It is not when
//   - the optimiser ended without a usable solution, or the cost is not finite;
//   - the fitted card is not valid;
//   - a free parameter ended at one of its bounds (the bound, not the data, sets it);
//   - a free parameter is not identifiable (the scaled Jacobian is rank-deficient along it), or
//     the model failed at the solution so that nothing could be checked;
//   - an experiment with a stated noise has residuals far above it (far_above_noise_rms).
// A fit that is not usable exits 1 and writes its card under a name that says so.
#include "inverse/fit/fit_file.hpp"
#include "inverse/fit/fit_result.hpp"

#include <string>
#include <vector>

namespace spifit::inverse {

// "Far above the noise": the residuals of n points are on average at least kFarAboveNoiseFloor
// times the stated noise, and so large that independent noise of the stated size would give a
// sum of squares that large with a probability below kFarAboveNoiseTail (chi-square with n
// degrees of freedom; fitting parameters only lowers the residuals, so the test errs on the
// side of "usable").
constexpr double kFarAboveNoiseTail = 1e-6;
constexpr double kFarAboveNoiseFloor = 2.0;
// The rms (in units of the stated noise) above which n points are far above it:
// max(kFarAboveNoiseFloor, sqrt(q / n)), q the chi-square quantile of n points exceeded with
// probability kFarAboveNoiseTail (4.89 for one point, 3.20 for three, 2.01 for thirteen, 2 from
// fourteen on).
double far_above_noise_rms(int points);

// Whether a physical value lies at the lower (-1) or upper (+1) bound of its parameter (within
// 1e-6 of the bound range, of the log range for log-scaled ones), or inside (0).
int bound_side(const ParameterSpec& spec, double value);

// Why the result is not usable, one plain sentence each; empty when it is usable. Reads the
// optimiser's verdict (result.usable, termination), the costs, the uncertainty analysis and
// the per-experiment costs that analyse_solution filled.
std::vector<std::string> unusable_reasons(const FitProblem& problem, const FitResult& result);

}  // namespace spifit::inverse
