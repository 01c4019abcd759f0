#include "inverse/fit/fit_assessment.hpp"

#include "forward/io/input_error.hpp"
#include "inverse/uncertainty/chi_square.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spifit::inverse {
namespace {

// A ratio in words: three significant digits, whole numbers from 1000 on ("234939", not "2.35e+05").
std::string ratio_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, std::abs(v) >= 1000.0 ? "%.0f" : "%.3g", v);
  return buf;
}

}  // namespace

double far_above_noise_rms(int points) {
  if (points <= 0) return kFarAboveNoiseFloor;
  const double q = chi_square_upper_quantile(points, kFarAboveNoiseTail);
  return std::max(kFarAboveNoiseFloor, std::sqrt(q / points));
}

int bound_side(const ParameterSpec& s, double value) {
  if (!std::isfinite(value) || !(s.upper > s.lower)) return 0;
  const bool logs = s.log_scale && s.lower > 0 && value > 0;
  const auto t = [logs](double v) { return logs ? std::log(v) : v; };
  const double tol = 1e-6 * (t(s.upper) - t(s.lower));
  if (t(value) <= t(s.lower) + tol) return -1;
  if (t(value) >= t(s.upper) - tol) return 1;
  return 0;
}

std::vector<std::string> unusable_reasons(const FitProblem& problem, const FitResult& r) {
  std::vector<std::string> out;
  char buf[512];
  if (!r.usable) out.push_back("the optimiser ended without a usable solution (" + r.termination + ")");
  try {
    material::validate_material_card(r.card);
  } catch (const io::InputError& e) {
    out.push_back("the fitted card is not valid: " + e.key() + " = " + e.value() + ": " + e.message());
  }
  if (!std::isfinite(r.cost_final)) {
    out.push_back("the cost at the solution is not finite (" + io::format_number(r.cost_final) +
                  "): the model cannot be evaluated there, or the data hold values it cannot reach");
  }
  const ParameterSet& ps = *problem.parameters;
  for (int k = 0; k < ps.num_free() && k < static_cast<int>(r.values.size()); ++k) {
    const ParameterSpec& s = ps.specs()[ps.free_indices()[k]];
    if (const int side = bound_side(s, r.values[k])) {
      out.push_back(s.name + " ended at its " + (side < 0 ? "lower" : "upper") + " bound (" + io::format_number(side < 0 ? s.lower : s.upper) +
                    "): the bound, not the data, sets its value");
    }
  }
  const auto& u = r.uncertainty;
  if (u.identifiable.empty() && r.usable && ps.num_free() > 0) {
    out.push_back("the model could not be evaluated at the solution, so its uncertainty and identifiability are unknown");
  }
  for (int k = 0; k < ps.num_free() && k < static_cast<int>(u.identifiable.size()); ++k) {
    if (!u.identifiable[k]) out.push_back(ps.specs()[ps.free_indices()[k]].name + " is not identifiable from these experiments");
  }
  for (std::size_t i = 0; i < r.experiment_costs.size() && i < problem.experiments.size(); ++i) {
    const Experiment& e = *problem.experiments[i];
    const ExperimentCost& c = r.experiment_costs[i];
    if (!e.noise_given() || c.noise_points <= 0) continue;
    const double rms = c.noise_rms;  // the weights taken out, over the points that count
    const double limit = far_above_noise_rms(c.noise_points);
    if (!(rms <= limit)) {
      std::snprintf(buf, sizeof buf,
                    "experiment %s: its residuals are on average %s times its stated noise over %d point%s (random noise of that size "
                    "stays below %.2f times): the data, their units or their noise do not match the model",
                    e.name().c_str(), ratio_text(rms).c_str(), c.noise_points, c.noise_points == 1 ? "" : "s", limit);
      out.push_back(buf);
    }
  }
  return out;
}

}  // namespace spifit::inverse
