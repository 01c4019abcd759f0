#include "reports/fit_verdict.hpp"

#include "inverse/fit/fit_assessment.hpp"
#include "inverse/fit/fit_output.hpp"
#include "reports/report_format.hpp"

#include <algorithm>
#include <cstdio>

namespace spifit::reports {

using inverse::FitRecord;
using namespace verdict_limits;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The rms of (simulated - measured) / divisor: fit.json's noise_rms where it has one (the weights
// taken out point by point, over the points of nonzero weight), else its rms without the
// experiment's weight, which multiplies every residual by its square root.
double unweighted_rms(const FitRecord::Experiment& e) {
  if (e.noise_points && std::isfinite(e.noise_rms)) return e.noise_rms;
  return e.rms / std::sqrt(e.weight > 0 ? e.weight : 1.0);
}
// The points the rms is over.
int rms_points(const FitRecord::Experiment& e) { return e.noise_points ? *e.noise_points : e.points; }

// Which divisor conditioned the residuals: the stated noise, or (none given) the range of the
// measured curve / the magnitude of the measured value. fit.json says so (noise_given); older
// files keep only the divisor, which is then recognised from the data.
Conditioning conditioning(const FitRecord::Experiment& e, const ExperimentData& d) {
  const bool scalar = is_scalar(e);
  if (e.noise_given) return *e.noise_given ? Conditioning::noise : scalar ? Conditioning::relative : Conditioning::range;
  if (!d.ok || !std::isfinite(e.scale) || !(e.scale > 0)) return Conditioning::unknown;
  const auto same = [&](double a) { return std::abs(e.scale - a) <= 1e-9 * std::max(std::abs(a), 1e-300); };
  if (scalar) return same(std::abs(d.measured[0])) ? Conditioning::relative : Conditioning::noise;
  double lo = INFINITY, hi = -INFINITY;
  for (double v : d.measured) {
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  return (hi > lo && same(hi - lo)) ? Conditioning::range : Conditioning::noise;
}

// Runs test on the signs of the final residuals: independent noise changes sign about every
// other point; a curve the model cannot follow gives long runs of one sign.
void runs_test(const ExperimentData& d, ExperimentVerdict& v) {
  std::vector<int> signs;
  for (std::size_t i = 0; i < d.measured.size(); ++i) {
    const double r = d.fitted[i] - d.measured[i];
    if (std::isfinite(r) && r != 0.0) signs.push_back(r > 0 ? 1 : -1);
  }
  const double n = static_cast<double>(signs.size());
  if (n < 10) return;
  double n1 = 0;
  int changes = 0;
  for (std::size_t i = 0; i < signs.size(); ++i) {
    if (signs[i] > 0) ++n1;
    if (i && signs[i] != signs[i - 1]) ++changes;
  }
  const double n2 = n - n1;
  v.sign_changes = changes;
  v.expected_sign_changes = 2.0 * n1 * n2 / n;  // expected runs - 1
  const double var = 2.0 * n1 * n2 * (2.0 * n1 * n2 - n) / (n * n * (n - 1.0));
  if (var > 0) v.runs_z = (changes - v.expected_sign_changes) / std::sqrt(var);
}

// Verdict when the divisor is the noise (or not recognised): rms in sigma (the experiment's
// weight, which scales every residual by its square root, taken out).
void judge_against_noise(const FitRecord::Experiment& e, ExperimentVerdict& v) {
  const double r = unweighted_rms(e);
  const bool noise = v.conditioning == Conditioning::noise;
  const char* u = noise ? "σ" : "× scale";
  char buf[320];
  if (noise && r > inverse::far_above_noise_rms(rms_points(e))) {
    v.level = 2;
    v.far_above_noise = true;
    std::snprintf(buf, sizeof buf, "FAR ABOVE THE NOISE: rms %.3g σ", r);
  } else if (is_scalar(e)) {
    if (r > kScalarConflictSigma) {
      v.level = 2;
      std::snprintf(buf, sizeof buf, "CONFLICT: off by %.1f %s", r, u);
    } else if (r > kScalarNoteSigma) {
      v.level = 1;
      std::snprintf(buf, sizeof buf, "off by %.1f %s", r, u);
    } else {
      std::snprintf(buf, sizeof buf, "within %.2f %s", r, u);
    }
  } else if (r > kCurveConflictRms) {
    v.level = 2;
    std::snprintf(buf, sizeof buf, "CONFLICT: rms %.2f %s", r, u);
  } else if (e.points >= 10 && noise && r * r > chi2_bound(e.points)) {
    v.level = 1;
    v.above_noise = true;
    std::snprintf(buf, sizeof buf, "rms %.2f σ: larger than the noise", r);
  } else if (r < kOverfitRms && e.points >= 10 && noise) {
    v.level = 1;
    std::snprintf(buf, sizeof buf, "rms %.2f σ: below the stated noise", r);
  } else {
    std::snprintf(buf, sizeof buf, "%s (rms %.2f %s)", noise ? "consistent with the noise" : "ok", r, u);
  }
  v.text = buf;
}

// Verdict when no noise was given: rms as a fraction of the data range / value.
void judge_against_range(const FitRecord::Experiment& e, ExperimentVerdict& v) {
  const char* of = v.conditioning == Conditioning::range ? "of the data range" : "of the value";
  const double rms = unweighted_rms(e);
  v.level = rms > kRangeConflict ? 2 : rms > kRangeNote ? 1 : 0;
  char buf[320];
  std::snprintf(buf, sizeof buf, "%s%.2f %% %s", v.level == 2 ? "POOR: rms " : "rms ", 100.0 * rms, of);
  v.text = buf;
}

const char* measured_what(Conditioning c) { return c == Conditioning::range ? "of the measured range" : "of the measured value"; }

std::string sigma_unit(Conditioning c) { return c == Conditioning::noise ? "σ" : "× scale"; }

// The warning or note on an experiment's verdict, if any.
void experiment_level_finding(const FitRecord::Experiment& e, const ExperimentVerdict& v, std::vector<Finding>& out) {
  const std::string yname = e.y.empty() ? "the observable" : e.y;
  const bool by_range = v.conditioning == Conditioning::range || v.conditioning == Conditioning::relative;
  char buf[640];
  if (v.level == 2 && std::isfinite(e.rms)) {
    if (by_range) {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s is fitted poorly: its rms residual is %.1f %% %s. No noise was given, so this cannot be "
                    "judged statistically, but the model does not follow these data.",
                    e.name.c_str(), 100.0 * unweighted_rms(e), measured_what(v.conditioning));
    } else if (v.far_above_noise) {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s: its residuals are %.3g times its stated noise over %d point%s, far more than random noise of that "
                    "size gives (%.2f): its data, their units or their noise do not match the model, so the fit is not usable.",
                    e.name.c_str(), unweighted_rms(e), rms_points(e), rms_points(e) == 1 ? "" : "s",
                    inverse::far_above_noise_rms(rms_points(e)));
    } else if (is_scalar(e)) {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s disagrees with the model: the fitted %s is %.1f %s away from the measured value. The data "
                    "conflict with the model or with the other experiments (or the stated noise is too small).",
                    e.name.c_str(), yname.c_str(), unweighted_rms(e), sigma_unit(v.conditioning).c_str());
    } else {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s disagrees with the model: its residuals are %.1f times the stated noise (rms %.2f; about 1 is "
                    "expected). The data conflict with the model or with the other experiments (or the stated noise is too "
                    "small); it carries %s of the total cost.",
                    e.name.c_str(), unweighted_rms(e), unweighted_rms(e), format_percent(v.share_cost).c_str());
    }
    out.push_back({2, buf});
    return;
  }
  if (v.level != 1) return;
  if (is_scalar(e)) {
    std::snprintf(buf, sizeof buf, "Experiment %s: the fitted %s is %.1f %s from the measured value.", e.name.c_str(), yname.c_str(),
                  unweighted_rms(e), sigma_unit(v.conditioning).c_str());
  } else if (v.above_noise) {
    std::snprintf(buf, sizeof buf,
                  "Experiment %s: residuals (rms %.2f σ) are significantly larger than the stated noise (random noise over "
                  "%d points stays below about %.2f σ): a mild disagreement with the model or the other experiments, or the "
                  "noise is understated.",
                  e.name.c_str(), unweighted_rms(e), e.points, std::sqrt(chi2_bound(e.points)));
  } else if (v.conditioning == Conditioning::noise) {
    std::snprintf(buf, sizeof buf,
                  "Experiment %s: residuals (rms %.2f σ) are clearly smaller than the stated noise; the noise may be overstated, "
                  "which widens the confidence intervals.",
                  e.name.c_str(), unweighted_rms(e));
  } else {
    std::snprintf(buf, sizeof buf, "Experiment %s: rms residual %.1f %% %s.", e.name.c_str(), 100.0 * unweighted_rms(e), measured_what(v.conditioning));
  }
  out.push_back({1, buf});
}

// Verdicts and findings of every experiment (shares of the total cost and points included).
void judge_experiments(const FitRecord& rec, const std::vector<ExperimentData>& data, FitVerdict& out) {
  double total = 0.0;
  long total_points = 0;
  for (const auto& e : rec.experiments) {
    if (std::isfinite(e.cost)) total += e.cost;
    total_points += e.points;
  }
  char buf[640];
  for (std::size_t i = 0; i < rec.experiments.size(); ++i) {
    const auto& e = rec.experiments[i];
    ExperimentVerdict v = judge_experiment(e, data[i]);
    v.share_cost = total > 0 ? e.cost / total : kNaN;
    v.share_points = total_points > 0 ? static_cast<double>(e.points) / static_cast<double>(total_points) : kNaN;
    experiment_level_finding(e, v, out.findings);
    if (std::isfinite(v.runs_z) && v.runs_z < kRunsZ) {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s: the residual changes sign only %d times in %d points (about %.0f expected for independent "
                    "noise): the deviation is systematic - the model's curve shape differs from the data, or the measurement "
                    "noise is correlated.",
                    e.name.c_str(), v.sign_changes, static_cast<int>(data[i].measured.size()), v.expected_sign_changes);
      out.findings.push_back({1, buf});
    }
    if (rec.experiments.size() >= 3 && std::isfinite(v.share_cost) && v.share_cost > kDominantShare) {
      std::snprintf(buf, sizeof buf, "Experiment %s carries %s of the total cost (%s of the points): it dominates the fit.", e.name.c_str(),
                    format_percent(v.share_cost).c_str(), format_percent(v.share_points).c_str());
      out.findings.push_back({1, buf});
    }
    out.experiments.push_back(v);
  }
}

bool near(double a, double b, double span) { return std::abs(a - b) <= 1e-6 * span; }

// "lower" / "upper" when the value lies within 1e-6 of the bound range (log range for
// log-scaled parameters) of that bound, else empty.
std::string bound_reached(const FitRecord::Parameter& p) {
  if (!std::isfinite(p.value) || !std::isfinite(p.lower) || !std::isfinite(p.upper) || !(p.upper > p.lower)) return {};
  const bool logs = p.log_scale && p.lower > 0 && p.value > 0;
  const double span = logs ? std::log(p.upper / p.lower) : p.upper - p.lower;
  const double v = logs ? std::log(p.value) : p.value;
  std::string at;
  if (near(v, logs ? std::log(p.lower) : p.lower, span)) at = "lower";
  if (near(v, logs ? std::log(p.upper) : p.upper, span)) at = "upper";
  return at;
}

void judge_parameters(const FitRecord& rec, FitVerdict& out) {
  for (const auto& p : rec.parameters) {
    out.at_bound.push_back(bound_reached(p));
    if (!std::isfinite(p.value) || !std::isfinite(p.lower) || !std::isfinite(p.upper) || !(p.upper > p.lower)) continue;
    const std::string& at = out.at_bound.back();
    bool told = false;  // fit.json already warns about this bound
    for (const auto& w : rec.warnings) told = told || (w.rfind(p.name + " ", 0) == 0 && w.find("bound") != std::string::npos);
    if (!at.empty() && !told) {
      out.findings.push_back({2, p.name + " sits at its " + at + " bound (" + format_significant(at == "lower" ? p.lower : p.upper) +
                                     "): the data push it beyond the allowed range, so the bound, not the data, sets its value and its "
                                     "uncertainty is not meaningful. Check the bounds, or the data that drive it."});
    }
    if (p.has_uncertainty && p.identifiable && std::isfinite(p.std_error) && p.value != 0 &&
        p.std_error / std::abs(p.value) > kRelErrNote) {
      out.findings.push_back({1, p.name + " is poorly determined: its standard error is " +
                                     format_percent(p.std_error / std::abs(p.value)) + " of its value."});
    }
  }
}

void judge_multistart(const FitRecord& rec, FitVerdict& out) {
  if (rec.multistart.starts <= 1) return;
  for (const auto& q : rec.parameters) {
    const auto& spread = rec.multistart.spread_at_best_cost;
    const auto s = std::find_if(spread.begin(), spread.end(), [&](const FitRecord::Spread& x) { return x.parameter == q.name; });
    if (s == spread.end() || !std::isfinite(s->min) || !std::isfinite(s->max) || !std::isfinite(q.value)) continue;
    const double tol = std::max(1e-3 * std::abs(q.value), std::isfinite(q.std_error) ? q.std_error : 0.0);
    if (s->max - s->min > tol) {
      out.findings.push_back({1, "Starts that reached the same best cost give " + q.name + " from " + format_significant(s->min) + " to " +
                                     format_significant(s->max) + ": the data do not determine it uniquely."});
    }
  }
}

void judge_correlations(const FitRecord& rec, FitVerdict& out) {
  const auto& names = rec.correlation.names;
  const auto& m = rec.correlation.matrix;
  char buf[640];
  for (std::size_t a = 0; a < m.size() && a < names.size(); ++a) {
    for (std::size_t b = a + 1; b < m[a].size() && b < names.size(); ++b) {
      const double r = m[a][b];
      if (!std::isfinite(r) || std::abs(r) < kCorrNote) continue;
      std::snprintf(buf, sizeof buf,
                    "%s and %s are %s correlated (r = %.3f): the data determine a combination of the two much better than "
                    "each one.",
                    names[a].c_str(), names[b].c_str(), std::abs(r) >= kCorrWarn ? "almost perfectly" : "strongly", r);
      out.findings.push_back({std::abs(r) >= kCorrWarn ? 2 : 1, buf});
    }
  }
}

}  // namespace

ExperimentVerdict judge_experiment(const FitRecord::Experiment& e, const ExperimentData& data) {
  ExperimentVerdict v;
  v.conditioning = conditioning(e, data);
  if (!is_scalar(e) && data.ok) runs_test(data, v);
  if (!std::isfinite(e.rms)) {
    v.level = 2;
    v.text = "no residual (the forward run failed?)";
  } else if (v.conditioning == Conditioning::range || v.conditioning == Conditioning::relative) {
    judge_against_range(e, v);
  } else {
    judge_against_noise(e, v);
  }
  return v;
}

std::string fitted_card_file(const FitRecord& rec) {
  return std::string("card") + inverse::fitted_file_suffix(!rec.usable || *rec.usable) + ".toml";
}

FitVerdict judge_fit(const FitRecord& rec, const std::vector<ExperimentData>& data) {
  FitVerdict out;
  if (rec.usable && !*rec.usable) {
    std::string why;
    for (const auto& w : rec.not_usable) why += (why.empty() ? "" : "; ") + w;
    if (why.empty()) why = rec.termination;  // a fit.json of an older spifit
    out.findings.push_back({2, "The result is NOT USABLE: " + why + ". Its card is written as " + fitted_card_file(rec) +
                                   ": do not use it as a material card."});
  } else if (rec.termination.rfind("NO_CONVERGENCE", 0) == 0 || rec.termination.rfind("FAILURE", 0) == 0) {
    out.findings.push_back({2, "The optimiser stopped without converging (" + rec.termination + "): the values may not be the best fit."});
  }
  for (const auto& w : rec.warnings) out.findings.push_back({2, w});
  for (const auto& n : rec.notes) out.findings.push_back({1, n});
  for (const auto& c : rec.conflicts) out.findings.push_back({2, "Conflict: " + c});
  judge_experiments(rec, data, out);
  judge_parameters(rec, out);
  judge_multistart(rec, out);
  judge_correlations(rec, out);
  return out;
}

}  // namespace spifit::reports
