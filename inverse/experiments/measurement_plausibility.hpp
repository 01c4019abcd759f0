#pragma once
// Are measured values plausible for their experiment? A unit in a data file's header that does
// not match its numbers (stress [GPa] over MPa values, force [kN] over N) converts them a
// thousandfold, and a fit then runs to its bounds: the reader names it before anything runs
// (docs/reference/file-formats.md, "Measurement files").
#include "forward/material/material_params.hpp"
#include "forward/scenes/common/scene.hpp"
#include "inverse/experiments/experiment.hpp"

#include <string>
#include <vector>

namespace spifit::inverse {

// Ratios of magnitudes beyond which measured values are odd (a note) or implausible (an error).
namespace plausibility {
constexpr double kOddRatio = 10.0;
constexpr double kImplausibleRatio = 100.0;
// FE forces against sigma_ref t R (sigma_ref: the card's flow stress at 20 % plastic strain,
// t the sheet thickness, R the tool radius): the thesis's steady cone forces (Table 9.1, about
// 840 N) are 1.1 times that scale.
constexpr double kForceScaleImplausible = 300.0;
constexpr double kRatioImplausible = 50.0;  // |F_a / F_b| of contour means
}  // namespace plausibility

// The largest |measured| against the largest |simulated| of a comparison at the start point
// (nothing to say when either is zero or the run failed).
MagnitudeCheck compare_magnitudes(const ExperimentCurve& curve);

// Measured values of an FE experiment (y: fx ... ftheta, a contour mean or ratio, z, thickness,
// or an observable; unit: its unit) against the scene's scales: forces against sigma_ref t R,
// section heights against the tool's depth, thicknesses against the sheet's.
MagnitudeCheck fe_magnitudes(const std::string& y, const std::string& unit, const std::vector<double>& measured, const scene::Scene& scene,
                             const material::MaterialParams<double>& material);

}  // namespace spifit::inverse
