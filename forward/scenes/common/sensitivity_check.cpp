#include "forward/scenes/common/sensitivity_check.hpp"

#include "forward/scenes/common/tool_force_history.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace spifit::scene {
namespace {

using ForceAt = std::map<double, Eigen::Vector3d>;  // tool travel -> force on the tool

std::unique_ptr<SceneResult> run_in_memory(const Scene& scene, const std::vector<std::string>& sensitivities, double tolerance,
                                           const std::string& what) {
  RunControl control;
  control.sensitivities = sensitivities;
  control.newton_tolerance = tolerance;
  auto r = scene.run(RunFiles(), control);
  if (!r->ok()) throw std::invalid_argument(what + " failed: " + r->message);
  return r;
}

ForceAt forces(const SceneResult& r) {
  ForceAt f;
  for (const auto& s : r.tool_force()->samples()) f[s.travel] = s.force;
  return f;
}

ForceAt moved(const Scene& scene, const std::string& name, double value, double tolerance, int* runs,
              const std::function<void(const std::string&)>& progress) {
  std::unique_ptr<Scene> s = scene.clone();
  char what[160];
  std::snprintf(what, sizeof what, "%s = %.17g", name.c_str(), value);
  if (progress) progress(what);
  if (const std::string why = s->set_input(name, value); !why.empty()) throw std::invalid_argument(std::string(what) + ": " + why);
  ++*runs;
  return forces(*run_in_memory(*s, {}, tolerance, what));
}

}  // namespace

SensitivityCheck check_sensitivities(const Scene& scene, const std::vector<std::string>& names, double relative_step, double tolerance,
                                     const std::function<void(const std::string&)>& progress) {
  if (!(relative_step > 0.0 && relative_step < 0.1)) throw std::invalid_argument("relative step must lie in (0, 0.1)");
  if (!(tolerance >= 0.0 && tolerance < 1.0)) throw std::invalid_argument("the solver tolerance must lie in [0, 1)");
  SensitivityCheck out;
  out.tolerance = tolerance;
  if (progress) progress("exact derivatives");
  const auto exact = run_in_memory(scene, names, tolerance, "the run with sensitivities");
  ++out.runs;
  if (!exact->force_sensitivities()) throw std::logic_error("a run with sensitivities without its table");
  const auto& samples = exact->tool_force()->samples();
  for (std::size_t k = 0; k < names.size(); ++k) {
    SensitivityCheckRow row;
    row.name = names[k];
    row.value = scene.input(names[k]);
    row.step = relative_step * (row.value != 0.0 ? std::abs(row.value) : 1.0);
    const ForceAt p1 = moved(scene, row.name, row.value + row.step, tolerance, &out.runs, progress);
    const ForceAt m1 = moved(scene, row.name, row.value - row.step, tolerance, &out.runs, progress);
    const ForceAt p4 = moved(scene, row.name, row.value + row.step / 4.0, tolerance, &out.runs, progress);
    const ForceAt m4 = moved(scene, row.name, row.value - row.step / 4.0, tolerance, &out.runs, progress);
    double scale = 0.0, diff = 0.0, spread = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const double t = samples[i].travel;
      if (!p1.count(t) || !m1.count(t) || !p4.count(t) || !m4.count(t)) continue;
      ++row.increments;
      const Eigen::Vector3d cd = (p1.at(t) - m1.at(t)) / (2.0 * row.step);
      const Eigen::Vector3d cd4 = (p4.at(t) - m4.at(t)) / (0.5 * row.step);
      const Eigen::Vector3d ex = exact->force_sensitivity(i).col(static_cast<Eigen::Index>(k));
      scale = std::max(scale, cd4.cwiseAbs().maxCoeff());
      const double d = (ex - cd4).cwiseAbs().maxCoeff();
      if (d > diff) {
        diff = d;
        row.worst_increment = static_cast<int>(i) + 1;
      }
      spread = std::max(spread, (cd - cd4).cwiseAbs().maxCoeff());
    }
    row.difference = scale > 0.0 ? diff / scale : diff;
    row.spread = scale > 0.0 ? spread / scale : spread;
    out.rows.push_back(row);
  }
  return out;
}

std::string format_sensitivity_check(const SensitivityCheck& c) {
  std::string s = "parameter            value         step h     increments  |exact - cd(h/4)|  |cd(h) - cd(h/4)|  worst at\n";
  char buf[256];
  for (const auto& r : c.rows) {
    std::snprintf(buf, sizeof buf, "%-18s %12.6g %12.4g %10d %18.2e %18.2e %9d  %s\n", r.name.c_str(), r.value, r.step, r.increments,
                  r.difference, r.spread, r.worst_increment, r.agrees() ? "ok" : "DIFFERS");
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "(differences over the largest |dF/dp| of the run; %d runs)\n", c.runs);
  s += buf;
  // At the scene's own tolerance (or any looser than 1e-10) the runs +h and -h stop at slightly
  // different distances from equilibrium (with friction Newton converges linearly), which
  // central differences follow.
  const char* verdict = c.agrees() ? "exact and central-difference derivatives agree within the central differences' own spread\n"
                        : c.tolerance == 0.0 || c.tolerance > 1e-10
                            ? "DIFFERS: an exact derivative lies outside the central differences' spread (smaller steps may settle it: "
                              "--relative-step; or runs converged further: --tolerance 1e-10)\n"
                            : "DIFFERS: an exact derivative lies outside the central differences' spread (smaller steps may settle it: "
                              "--relative-step)\n";
  s.append(verdict);
  return s;
}

}  // namespace spifit::scene
