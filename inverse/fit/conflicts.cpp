#include "inverse/fit/conflicts.hpp"

#include "forward/io/input_error.hpp"
#include "inverse/fit/ceres_fit.hpp"

#include <cmath>
#include <cstdio>

namespace spifit::inverse {

namespace {
// Where the joint value lies with respect to the two single-experiment intervals.
std::string joint_position(double v, const FitResult::Alone& A, const FitResult::Alone& B, int k) {
  const bool in_a = A.ci95_lower[k] <= v && v <= A.ci95_upper[k];
  const bool in_b = B.ci95_lower[k] <= v && v <= B.ci95_upper[k];
  if (in_a && in_b) return "lies in both intervals";
  if (in_a) return "lies in " + A.experiment + "'s interval only, so " + B.experiment + " is not satisfied";
  if (in_b) return "lies in " + B.experiment + "'s interval only, so " + A.experiment + " is not satisfied";
  return "lies in neither interval";
}
}  // namespace

void analyse_conflicts(const FitProblem& fp, const FitRunOptions& options, FitResult* out) {
  const ParameterSet& ps = *fp.parameters;
  std::vector<ParameterSpec> specs = ps.specs();
  for (int k = 0; k < ps.num_free(); ++k) specs[ps.free_indices()[k]].initial = out->values[k];
  out->per_experiment.clear();
  out->conflicts.clear();
  for (const auto& e : fp.experiments) {
    FitProblem one;
    one.name = fp.name + " [" + e->name() + " alone]";
    one.file = fp.file;
    one.parameters = std::make_unique<ParameterSet>(ps.base(), specs, ps.normalise_hill());
    one.experiments = {e};
    one.settings = fp.settings;
    FitRunOptions o = options;
    o.algorithm = "levenberg_marquardt";
    if (o.progress) {
      o.progress->set_phase(e->name() + " alone");
      // One experiment: its scene file's point and (central differences) 2p neighbours, if it has FE runs.
      o.progress->set_runs_per_iteration(e->scene_file().empty() ? 0 : e->exact_columns() > 0 ? 1 : 1 + 2L * one.parameters->num_free());
    }
    const FitResult r = fit_with_ceres(one, o);
    FitResult::Alone a;
    a.experiment = e->name();
    a.usable = r.usable;
    a.values = r.values;
    a.ci95_lower = r.uncertainty.ci95_lower;
    a.ci95_upper = r.uncertainty.ci95_upper;
    a.identifiable = r.uncertainty.identifiable;
    out->forward_runs += r.forward_runs;
    out->per_experiment.push_back(a);
  }
  const auto& pe = out->per_experiment;
  for (int k = 0; k < ps.num_free(); ++k) {
    const std::string& name = ps.specs()[ps.free_indices()[k]].name;
    for (std::size_t a = 0; a < pe.size(); ++a) {
      for (std::size_t b = a + 1; b < pe.size(); ++b) {
        const auto& A = pe[a];
        const auto& B = pe[b];
        if (!A.usable || !B.usable || A.identifiable.size() <= std::size_t(k) || B.identifiable.size() <= std::size_t(k)) continue;
        if (!A.identifiable[k] || !B.identifiable[k]) continue;
        if (!std::isfinite(A.ci95_lower[k]) || !std::isfinite(B.ci95_lower[k])) continue;
        if (A.ci95_upper[k] < B.ci95_lower[k] || B.ci95_upper[k] < A.ci95_lower[k]) {
          auto g4 = [](double v) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.4g", v);
            return std::string(buf);
          };
          auto fmt = [&](const FitResult::Alone& x) { return g4(x.values[k]) + " [" + g4(x.ci95_lower[k]) + ", " + g4(x.ci95_upper[k]) + "]"; };
          out->conflicts.push_back("experiments " + A.experiment + " and " + B.experiment + " disagree on " + name + ": " +
                                   A.experiment + " alone gives " + fmt(A) + ", " + B.experiment + " alone gives " + fmt(B) +
                                   "; the joint value " + g4(out->values[k]) + " " + joint_position(out->values[k], A, B, k) + ".");
        }
      }
    }
  }
}

}  // namespace spifit::inverse
