#pragma once
// What a fit report concludes from a fit (docs/guide/reading-reports.md "Rules for verdicts and findings"):
// a verdict per experiment (is it consistent with its noise, or in conflict), parameters at a
// bound, and findings in plain words: warnings (problems that need attention) and notes.
#include "inverse/fit/fit_record.hpp"
#include "reports/experiment_data.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace spifit::reports {

// Thresholds of the verdicts.
namespace verdict_limits {
constexpr double kCurveConflictRms = 2.0;  // curve, noise given: rms above this many sigma
constexpr double kScalarNoteSigma = 2.0;   // scalar, noise given: |residual| above this many sigma
constexpr double kScalarConflictSigma = 3.0;
constexpr double kOverfitRms = 0.5;  // curve, noise given: rms below this (>= 10 points)
constexpr double kRangeNote = 0.02;  // no noise given: rms as a fraction of the range / value
constexpr double kRangeConflict = 0.05;
constexpr double kRunsZ = -3.0;  // runs test of the residual signs
constexpr double kCorrNote = 0.95, kCorrWarn = 0.99;
constexpr double kRelErrNote = 0.5;  // std error / |value|
constexpr double kDominantShare = 0.5;
}  // namespace verdict_limits

// Mean square of n independent standard-normal residuals: chi2(n)/n, mean 1, sd sqrt(2/n).
// Above 1 + 3 sd the residuals are significantly larger than the stated noise.
inline double chi2_bound(int n) { return 1.0 + 3.0 * std::sqrt(2.0 / n); }

// What divided the residuals of an experiment: the stated noise, the range of the measured
// curve or |measured value| (no noise given), or unknown (neither recognised).
enum class Conditioning { noise, range, relative, unknown };

struct ExperimentVerdict {
  Conditioning conditioning = Conditioning::unknown;
  double share_cost = std::numeric_limits<double>::quiet_NaN();
  double share_points = std::numeric_limits<double>::quiet_NaN();
  int level = 0;             // 0 ok, 1 note, 2 conflict
  bool above_noise = false;  // rms significantly above 1 (noise given), below the conflict level
  bool far_above_noise = false;  // rms above inverse::far_above_noise_rms: the fit is not usable
  std::string text;          // e.g. "consistent with the noise (rms 0.98 σ)"
  // Runs test of the residual signs (curves with >= 10 non-zero residuals).
  int sign_changes = -1;
  double expected_sign_changes = std::numeric_limits<double>::quiet_NaN();
  double runs_z = std::numeric_limits<double>::quiet_NaN();
};

struct Finding {
  int level = 2;  // 2 warning, 1 note
  std::string text;
};

struct FitVerdict {
  std::vector<ExperimentVerdict> experiments;  // in the order of record.experiments
  std::vector<std::string> at_bound;           // per record.parameters: "lower", "upper" or empty
  std::vector<Finding> findings;               // warnings and notes, in the order the report lists them
};

// The verdict on one experiment, without the shares of the total cost and points.
ExperimentVerdict judge_experiment(const inverse::FitRecord::Experiment& e, const ExperimentData& data);

// The fitted card's file in the fit's directory: card.toml, or card_NOT_USABLE.toml when the
// record says the fit is not usable.
std::string fitted_card_file(const inverse::FitRecord& record);

// data: one entry per experiment of the record (read_fit_data).
FitVerdict judge_fit(const inverse::FitRecord& record, const std::vector<ExperimentData>& data);

}  // namespace spifit::reports
