#include "reports/fit_sections.hpp"

#include "reports/report_format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace spifit::reports {

using inverse::FitRecord;

namespace {

std::string count(const std::optional<long>& v) { return v ? std::to_string(*v) : std::string("n/a"); }

std::string seconds(double s) { return format_significant(s, 3); }

void add_runs_by_scene(Document& d, const FitRecord& rec) {
  Table t;
  t.id = "runs-by-scene";
  t.header = {"scene file", "runs", "failed", "retried", "wall time of the runs [s]", "median run [s]"};
  t.right = {false, true, true, true, true, true};
  for (const auto& f : rec.runs_by_scene) {
    t.rows.push_back({cell(f.scene), cell(std::to_string(f.runs)), cell(std::to_string(f.failures), f.failures > 0 ? CellStyle::bad : CellStyle::plain),
                      cell(std::to_string(f.retried), f.retried > 0 ? CellStyle::warn : CellStyle::plain), cell(seconds(f.seconds)),
                      cell(seconds(f.median_seconds))});
  }
  d.table(t);
  d.para({{"Per scene file: its runs (a retry with half the increment is a run of its own), the parameter points whose run "
           "failed (also after the retry, or whose inputs the scene refused; fit.json failed_runs says why), the retries, "
           "and the wall time of the runs, summed and the median of one."}});
}

}  // namespace

void add_information_shares(Document& d, const FitRecord& rec) {
  const auto& exps = rec.experiments;
  if (std::none_of(exps.begin(), exps.end(), [](const FitRecord::Experiment& x) { return !x.information_share.empty(); })) return;
  d.heading(3, "Which experiment informs which parameter", "information");
  Table t;
  t.id = "information";
  t.header = {"experiment"};
  t.right = {false};
  for (const auto& q : rec.parameters) {
    t.header.push_back(q.name);
    t.right.push_back(true);
  }
  for (const auto& x : exps) {
    std::vector<Cell> row{cell(x.name)};
    for (std::size_t k = 0; k < rec.parameters.size(); ++k) {
      const double s = k < x.information_share.size() ? x.information_share[k] : std::numeric_limits<double>::quiet_NaN();
      Cell c = cell(std::isfinite(s) ? format_percent(s) : "n/a");
      if (std::isfinite(s) && s >= 0.5) c.style = CellStyle::good;
      row.push_back(c);
    }
    t.rows.push_back(row);
  }
  d.table(t);
  d.para({{"Each parameter's Fisher information at the solution (the diagonal of JᵀJ, J the Jacobian of the conditioned "
           "residuals) split by experiment: the share of the rows of each experiment. A column adds up to 100 %; the experiments "
           "with the large shares fix the parameter, one near 0 % hardly moves it. It counts each parameter alone: two experiments "
           "may share the information on a parameter only through a correlated combination (see the correlation matrix). "
           "n/a: no experiment responds to the parameter."}});
}

namespace {
std::string jacobian_words(const std::string& j) {
  if (j == "jets") return "exact (Jets)";
  if (j == "exact") return "exact (FE run)";
  if (j == "central") return "central differences";
  return "–";  // a fit.json of an older spifit
}
}  // namespace

void add_forward_runs(Document& d, const FitRecord& rec) {
  d.heading(2, "Forward runs", "forward-runs");
  const auto& exps = rec.experiments;
  const bool counted = std::any_of(exps.begin(), exps.end(), [](const FitRecord::Experiment& x) { return x.evaluations.has_value(); });
  if (!counted && rec.runs_by_scene.empty()) {
    d.para({{"fit.json does not count the forward runs per experiment (written by an older spifit)."}});
    return;
  }
  const bool fe = std::any_of(exps.begin(), exps.end(), [](const FitRecord::Experiment& x) { return x.scene_runs.has_value(); });
  Table t;
  t.id = "forward-runs";
  t.header = {"experiment", "kind", "evaluations", "Jacobian"};
  t.right = {false, false, true, false};
  if (fe) {
    t.header.insert(t.header.end(), {"scene runs", "wall time of its runs [s]"});
    t.right.insert(t.right.end(), {true, true});
  }
  for (const auto& x : exps) {
    std::vector<Cell> row{cell(x.name), cell(x.kind), cell(count(x.evaluations)), cell(jacobian_words(x.jacobian))};
    if (fe) {
      row.push_back(cell(x.scene_runs ? std::to_string(*x.scene_runs) : "–"));
      row.push_back(cell(x.scene_runs ? seconds(x.run_seconds) : "–"));
    }
    t.rows.push_back(row);
  }
  d.table(t);
  std::string text =
      "Evaluations: how often the fit computed the experiment's residuals: its steps, its Jacobians and the analysis at the "
      "solution. Jacobian: exact through Jets (a material point: one evaluation), exact through the FE run (direct "
      "differentiation: one run with sensitivities, residuals and Jacobian from it) or central differences (1 + 2 runs per "
      "free parameter).";
  if (fe) {
    text += " Experiments on the same scene file share its runs, one per parameter point: a run counts for the experiment that "
            "asked for the point first. Material-point experiments run in memory within their evaluations (–).";
  }
  d.para({{text}});
  if (!rec.runs_by_scene.empty()) add_runs_by_scene(d, rec);
}

}  // namespace spifit::reports
