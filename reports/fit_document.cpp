#include "forward/material/material_inputs.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "reports/fit_document.hpp"

#include "reports/fit_sections.hpp"
#include "reports/report_format.hpp"

#include "forward/material/hardening/hardening_laws.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace spifit::reports {

using inverse::FitRecord;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string fmt(double v, int digits = 6) { return format_significant(v, digits); }

template <typename T>
double number(const std::optional<T>& v) {
  return v ? static_cast<double>(*v) : kNaN;
}

std::string link_at(const std::vector<std::string>& links, std::size_t i) { return i < links.size() ? links[i] : std::string(); }

CellStyle bad_if(bool b) { return b ? CellStyle::bad : CellStyle::plain; }

bool is_ceres(const std::string& algorithm) { return algorithm == "levenberg_marquardt" || algorithm == "dogleg"; }

std::string conditioning_text(const FitRecord::Experiment& e, Conditioning c) {
  switch (c) {
    case Conditioning::noise: return "noise σ = " + with_unit(fmt(e.scale, 4), e.y_unit);
    case Conditioning::range: return "data range " + with_unit(fmt(e.scale, 4), e.y_unit) + " (no noise given)";
    case Conditioning::relative: return "|value| " + fmt(e.scale, 4) + " (no noise given)";
    case Conditioning::unknown: break;
  }
  return "scale " + fmt(e.scale, 4);
}

std::string data_file_of(const FitRecord::Experiment& e) {
  return e.data_file.empty() ? "experiments/" + e.name + ".csv" : e.data_file;
}

void add_intro_and_warnings(Document& d, const FitReportContent& c) {
  const FitRecord& rec = c.record;
  Inline intro{{"Fit file "}, {rec.fit_file.empty() ? "(unknown)" : rec.fit_file, false, true}};
  if (!rec.spifit_version.empty()) intro.push_back({", spifit " + rec.spifit_version});
  const std::string card = fitted_card_file(rec);
  intro.push_back({". Fitted card: "});
  intro.push_back({card, false, true, card});
  intro.push_back({"; all numbers: "});
  intro.push_back({"fit.json", false, true, "fit.json"});
  intro.push_back({"."});
  d.para(intro);

  std::vector<Inline> warn, notes;
  for (const auto& f : c.verdict.findings) (f.level == 2 ? warn : notes).push_back({{f.text}});
  d.heading(2, "Warnings", "warnings");
  if (!warn.empty()) {
    d.callout(CalloutKind::warning,
              "WARNING: " + std::to_string(warn.size()) + (warn.size() == 1 ? " problem needs attention" : " problems need attention"), warn);
  } else {
    d.callout(CalloutKind::ok, "No warnings",
              {{{"The fit converged, every parameter is identifiable and within its bounds, and every experiment agrees with the fitted model."}}});
  }
  if (!notes.empty()) d.callout(CalloutKind::note, "Notes", notes);
}

void add_summary(Document& d, const FitReportContent& c) {
  const FitRecord& rec = c.record;
  const auto& u = rec.uncertainty;
  d.heading(2, "Summary", "summary");
  Table s;
  s.id = "summary";
  s.header = {"item", "value"};
  auto row = [&](const std::string& k, const std::string& v, CellStyle style = CellStyle::plain) { s.rows.push_back({cell(k), cell(v, style)}); };
  row("fit file", rec.fit_file.empty() ? "n/a" : rec.fit_file);
  row("algorithm", rec.algorithm.empty() ? "n/a" : rec.algorithm);
  row("termination", rec.termination.empty() ? "n/a" : rec.termination);
  if (rec.seed && !is_ceres(rec.algorithm)) row("seed", fmt(*rec.seed, 12));
  // A usable result with warnings is amber: read them before using the card.
  std::size_t warnings = 0;
  for (const auto& f : c.verdict.findings) warnings += f.level == 2 ? 1 : 0;
  if (rec.usable && !*rec.usable) row("result usable", "NO (see the warnings): " + fitted_card_file(rec), CellStyle::bad);
  else if (rec.usable && warnings > 0)
    row("result usable", "yes, with " + std::to_string(warnings) + (warnings == 1 ? " warning" : " warnings") + " (see above)", CellStyle::warn);
  else if (rec.usable) row("result usable", "yes", CellStyle::good);
  row("iterations", fmt(number(rec.iterations), 10));
  row("forward runs", fmt(number(rec.forward_runs), 12));
  row("wall time", std::isfinite(rec.wall_seconds) ? fmt(rec.wall_seconds, 3) + " s" : "n/a");
  row("cost initial", fmt(rec.cost_initial));
  row("cost final", fmt(rec.cost_final));
  if (std::isfinite(rec.cost_initial) && std::isfinite(rec.cost_final) && rec.cost_final > 0) {
    row("cost reduction", "factor " + fmt(rec.cost_initial / rec.cost_final, 4));
  }
  row("residuals / free parameters / degrees of freedom",
      fmt(number(u.residuals), 10) + " / " + fmt(number(u.parameters), 10) + " / " + fmt(number(u.dof), 10));
  bool all_noise = !rec.experiments.empty();
  for (const auto& v : c.verdict.experiments) all_noise = all_noise && v.conditioning == Conditioning::noise;
  if (std::isfinite(u.sigma2)) {
    const double limit = verdict_limits::kCurveConflictRms * verdict_limits::kCurveConflictRms;
    row("σ² = SSE / dof", fmt(u.sigma2, 4) + " (rms residual " + fmt(std::sqrt(u.sigma2), 3) + ")", bad_if(all_noise && u.sigma2 > limit));
  }
  d.table(s);
  d.para({{"Cost = " + (rec.cost_definition.empty() ? std::string("1/2 sum of squared conditioned residuals") : rec.cost_definition) +
           ". When noise is given for every experiment, σ² near 1 means the residuals are as large as the stated noise."}});
}

// The unit of a fitted parameter: a card parameter's (swift.K: MPa) or a scene input's
// (tool.radius: mm); "-" for dimensionless ones (hill.F, contact.friction).
std::string parameter_unit(const std::string& name) {
  std::vector<io::InputInfo> infos = material::material_input_infos();
  for (const auto& kind : scene::scene_kinds()) infos.insert(infos.end(), kind.inputs.begin(), kind.inputs.end());
  for (const auto& info : infos)
    if (info.name == name) return info.unit.empty() ? "-" : info.unit;
  return "-";
}

void add_parameters(Document& d, const FitReportContent& c) {
  const FitRecord& rec = c.record;
  d.heading(2, "Parameters", "parameters");
  Table p;
  p.id = "parameters";
  p.header = {"parameter", "unit", "initial", "value", "std. error", "95 % interval", "lower", "upper", "identifiable", "note"};
  p.right = {false, false, true, true, true, true, true, true, false, false};
  for (std::size_t k = 0; k < rec.parameters.size(); ++k) {
    const auto& q = rec.parameters[k];
    const std::string& at = c.verdict.at_bound[k];
    std::string note;
    if (!at.empty()) note = "AT " + at + " BOUND";
    if (q.log_scale) note += std::string(note.empty() ? "" : "; ") + "log scale";
    const bool ci_known = std::isfinite(q.ci95_lower) && std::isfinite(q.ci95_upper);
    const std::string ci = ci_known ? "[" + fmt(q.ci95_lower) + ", " + fmt(q.ci95_upper) + "]" : "n/a";
    const std::string ident = !q.has_uncertainty ? "n/a" : q.identifiable ? "yes" : "NO";
    p.rows.push_back({cell(q.name), cell(parameter_unit(q.name)), cell(fmt(q.initial)), cell(fmt(q.value), bad_if(!at.empty())), cell(fmt(q.std_error, 4)), cell(ci),
                      cell(fmt(q.lower)), cell(fmt(q.upper)), cell(ident, bad_if(!q.identifiable)), cell(note, bad_if(!at.empty()))});
  }
  d.table(p);
  d.para({{"Standard errors and 95 % intervals are linearised at the solution (covariance σ² (JᵀJ)⁻¹, Student t quantile " +
           fmt(rec.uncertainty.t_quantile_975, 4) + "); they assume the model is right and the residuals are independent."}});
  if (!rec.fixed.empty()) {
    Table fx;
    fx.id = "fixed";
    fx.header = {"fixed parameter", "value"};
    for (const auto& f : rec.fixed) fx.rows.push_back({cell(f.name), cell(f.expression.empty() ? fmt(f.value, 10) : f.expression)});
    d.table(fx);
  }
}

// Where a card parameter's value comes from in this fit.
std::string parameter_origin(const FitRecord& rec, const std::string& name) {
  for (const auto& q : rec.parameters)
    if (q.name == name) return "fitted";
  for (const auto& f : rec.fixed)
    if (f.name == name) return f.expression.empty() ? "fixed in the fit file" : "= " + f.expression;
  // N sets L and M (thesis: N = L = M).
  if (name == "hill.L" || name == "hill.M") return parameter_origin(rec, "hill.N") == "fitted" ? "= hill.N (fitted)" : "start card";
  return "start card";
}

// What a card with a registered yield function (Yld2000-2d) predicts: uniaxial tension at 0, 45
// and 90 degrees, equibiaxial tension and in-plane shear, from its gradient.
void add_registered_yield_predictions(Document& d, const material::MaterialCard& card) {
  const auto& p = card.params;
  Table r;
  r.id = "card_predictions";
  r.header = {"stress state", "r-value", "initial yield stress"};
  r.right = {false, true, true};
  const double s0 = p.plastic ? material::hardening_stress(p, 0.0) : kNaN;
  for (double deg : {0.0, 45.0, 90.0}) {
    const double a = deg * std::numbers::pi / 180.0;
    r.rows.push_back({cell("uniaxial at " + fmt(deg, 3) + "° to RD"), cell(fmt(material::uniaxial_r_value(p, a), 4)),
                      cell(with_unit(fmt(s0 / material::uniaxial_yield_factor(p, a), 4), "MPa"))});
  }
  r.rows.push_back({cell("equibiaxial"), cell(fmt(material::equibiaxial_r_value(p), 4)),
                    cell(with_unit(fmt(s0 / material::equibiaxial_yield_factor(p), 4), "MPa"))});
  r.rows.push_back({cell("in-plane shear"), cell("-"), cell(with_unit(fmt(s0 / material::shear_yield_factor(p), 4), "MPa"))});
  d.table(r);
  d.para({{"What the card predicts (" + material::yield_function_title(p.yield.law) +
           ", from its flow direction; yield stress sigma_F(0) over the equivalent stress of a unit stress in each state). "
           "The equibiaxial r-value is d eps_TD / d eps_RD."}});
}

// The whole card as written, fixed parameters too, and what it predicts at 0, 45 and 90 degrees
// to RD (closed forms of Hill 1948, thesis eq. C.2; initial yield stress K eps0^n scaled by the
// uniaxial factor).
void add_card(Document& d, const FitReportContent& c) {
  if (!c.card) return;
  const material::MaterialCard& card = *c.card;
  const auto& p = card.params;
  d.heading(2, "The fitted card", "card");
  Table t;
  t.id = "card";
  t.header = {"parameter", "unit", "value", "from"};
  t.right = {false, false, true, false};
  for (const auto& in : material::material_inputs()) {
    if (!material::input_in_use(p, in)) continue;
    t.rows.push_back({cell(in.info.name), cell(in.info.unit.empty() ? "-" : in.info.unit), cell(fmt(material::material_field(p, in.field))),
                      cell(parameter_origin(c.record, in.info.name))});
    if (in.info.name == "hill.N") {
      t.rows.push_back({cell("hill.L"), cell("-"), cell(fmt(p.L)), cell(parameter_origin(c.record, "hill.L"))});
      t.rows.push_back({cell("hill.M"), cell("-"), cell(fmt(p.M)), cell(parameter_origin(c.record, "hill.M"))});
    }
  }
  d.table(t);
  if (p.yield.active()) return add_registered_yield_predictions(d, card);
  const material::Hill48 h = card.hill();
  Table r;
  r.id = "card_predictions";
  r.header = {"angle to RD", "r-value", "initial yield stress"};
  r.right = {true, true, true};
  const double s0 = p.plastic ? material::hardening_stress(p, 0.0) : kNaN;
  for (double deg : {0.0, 45.0, 90.0}) {
    const double a = deg * std::numbers::pi / 180.0;
    r.rows.push_back({cell(fmt(deg, 3) + "°"), cell(fmt(material::r_value_at_angle(h, a), 4)),
                      cell(with_unit(fmt(s0 / material::uniaxial_stress_factor(h, a), 4), "MPa"))});
  }
  d.table(r);
  d.para({{"What the card predicts in uniaxial tension (Hill 1948 closed forms, thesis eq. C.2; yield stress K ε0ⁿ over the "
           "uniaxial factor of each direction)."}});
}

void add_experiments(Document& d, const FitReportContent& c) {
  d.heading(2, "Experiments", "experiments");
  Table t;
  t.id = "experiments";
  t.header = {"experiment", "kind", "points", "observable", "residuals divided by", "weight", "cost", "share of cost", "share of points", "rms", "verdict"};
  t.right = {false, false, true, false, false, true, true, true, true, true, false};
  for (std::size_t i = 0; i < c.record.experiments.size(); ++i) {
    const auto& x = c.record.experiments[i];
    const auto& v = c.verdict.experiments[i];
    std::string obs = x.y.empty() ? "n/a" : experiment_axis_label(x, false, "");
    if (!is_scalar(x) && !x.x.empty()) obs += " vs " + experiment_axis_label(x, true, "x");
    const CellStyle vstyle = v.level == 2 ? CellStyle::bad : v.level == 1 ? CellStyle::warn : CellStyle::good;
    t.rows.push_back({cell(x.name), cell(x.kind), cell(std::to_string(x.points)), cell(obs), cell(conditioning_text(x, v.conditioning)),
                      cell(fmt(x.weight, 4)), cell(fmt(x.cost, 4)), cell(format_percent(v.share_cost), bad_if(v.level == 2)),
                      cell(format_percent(v.share_points)), cell(fmt(x.rms, 4), bad_if(v.level == 2)), cell(v.text, vstyle)});
  }
  d.table(t);
  d.para({{"rms is the root-mean-square of the conditioned residuals (fitted - measured) / divisor. With the measurement noise as "
           "divisor it should be about 1; far above 1 means these data disagree with the model (or with the other experiments), "
           "well below 1 means the noise is overstated. An experiment with a large share of the cost but few points pulls the fit "
           "towards itself."}});
}

std::string interval_text(double v, double lo, double hi) {
  std::string t = fmt(v, 4);
  if (std::isfinite(lo) && std::isfinite(hi)) t += " [" + fmt(lo, 4) + ", " + fmt(hi, 4) + "]";
  return t;
}

// The cell of one parameter of an experiment fitted alone; warn when its interval excludes
// the joint value.
Cell alone_cell(const FitRecord::Alone& al, const FitRecord::Parameter& q) {
  const auto& ps = al.parameters;
  const auto v = std::find_if(ps.begin(), ps.end(), [&](const FitRecord::AloneValue& a) { return a.parameter == q.name; });
  if (v == ps.end() || !al.usable) return cell("n/a");
  if (!v->identifiable) return cell("not determined");
  const bool excludes = std::isfinite(v->ci95_lower) && std::isfinite(v->ci95_upper) && (q.value < v->ci95_lower || q.value > v->ci95_upper);
  return cell(interval_text(v->value, v->ci95_lower, v->ci95_upper), excludes ? CellStyle::warn : CellStyle::plain);
}

void add_per_experiment(Document& d, const FitRecord& rec) {
  if (rec.per_experiment.empty()) return;
  d.heading(3, "Each experiment fitted alone", "per-experiment");
  Table a;
  a.id = "per-experiment";
  a.header = {"fitted to"};
  a.right = {false};
  for (const auto& q : rec.parameters) {
    a.header.push_back(q.name);
    a.right.push_back(true);
  }
  std::vector<Cell> joint{cell("all experiments (the fit)")};
  for (const auto& q : rec.parameters) joint.push_back(cell(interval_text(q.value, q.ci95_lower, q.ci95_upper)));
  a.rows.push_back(joint);
  for (const auto& al : rec.per_experiment) {
    std::vector<Cell> r{cell(al.experiment + (al.usable ? "" : " (failed)"), bad_if(!al.usable))};
    for (const auto& q : rec.parameters) r.push_back(alone_cell(al, q));
    a.rows.push_back(r);
  }
  d.table(a);
  d.para({{"Value and 95 % interval of each parameter when only that experiment is fitted (from the joint solution). "
           "Experiments whose intervals do not overlap disagree on the parameter (listed under Warnings); a highlighted "
           "interval does not contain the joint value. \"not determined\": the experiment alone does not fix the parameter."}});
}

void add_multistart(Document& d, const FitRecord& rec) {
  const auto& m = rec.multistart;
  if (m.starts <= 1) return;
  d.heading(3, "Multi-start", "multistart");
  d.para({{std::to_string(m.starts) + " starts; the best is start " + (m.best_start >= 0 ? std::to_string(m.best_start) : std::string("n/a")) +
           "; " + (m.starts_at_best_cost >= 0 ? std::to_string(m.starts_at_best_cost) : std::string("n/a")) + " reached the best cost."}});
  Table t;
  t.id = "multistart";
  t.header = {"start", "usable", "cost"};
  t.right = {true, false, true};
  for (const auto& q : rec.parameters) {
    t.header.push_back(q.name);
    t.right.push_back(true);
  }
  std::vector<Cell> spread{cell("spread at the best cost"), cell(""), cell("")};
  for (const auto& q : rec.parameters) {
    const auto& sp = m.spread_at_best_cost;
    const auto s = std::find_if(sp.begin(), sp.end(), [&](const FitRecord::Spread& x) { return x.parameter == q.name; });
    const bool ok = s != sp.end() && std::isfinite(s->min) && std::isfinite(s->max);
    spread.push_back(cell(ok ? fmt(s->min) + " to " + fmt(s->max) : "n/a"));
  }
  t.rows.push_back(spread);
  const std::size_t shown = std::min<std::size_t>(m.solutions.size(), 30);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& so = m.solutions[i];
    std::vector<Cell> r{cell(std::to_string(i) + (static_cast<int>(i) == m.best_start ? " (best)" : "")),
                        cell(so.usable ? "yes" : "no", so.usable ? CellStyle::plain : CellStyle::warn), cell(fmt(so.cost))};
    for (std::size_t k = 0; k < rec.parameters.size(); ++k) r.push_back(cell(k < so.values.size() ? fmt(so.values[k]) : "n/a"));
    t.rows.push_back(r);
  }
  d.table(t);
  if (m.solutions.size() > shown) {
    d.para({{"(first " + std::to_string(shown) + " of " + std::to_string(m.solutions.size()) + " starts shown; all are in fit.json)"}});
  }
}

void add_scalars(Document& d, const FitReportContent& c) {
  const auto& exps = c.record.experiments;
  if (std::none_of(exps.begin(), exps.end(), [](const FitRecord::Experiment& x) { return is_scalar(x); })) return;
  d.heading(3, "Scalar experiments", "scalars");
  Table sc;
  sc.id = "scalars";
  sc.header = {"experiment", "observable", "measured", "initial", "fitted", "fitted - measured", "(fitted - measured) / divisor"};
  sc.right = {false, false, true, true, true, true, true};
  for (std::size_t i = 0; i < exps.size(); ++i) {
    const auto& x = exps[i];
    const auto& data = c.data[i];
    if (!is_scalar(x)) continue;
    if (!data.ok) {
      sc.rows.push_back({cell(x.name), cell(x.y), cell("n/a"), cell("n/a"), cell("n/a"), cell("n/a"), cell("n/a")});
      continue;
    }
    const double diff = data.fitted[0] - data.measured[0];
    sc.rows.push_back({cell(x.name), cell(axis_label(x.y, x.y_unit, "n/a")), cell(fmt(data.measured[0])), cell(fmt(data.initial[0])),
                       cell(fmt(data.fitted[0])), cell(fmt(diff, 4)), cell(fmt(diff / x.scale, 3), bad_if(c.verdict.experiments[i].level == 2))});
  }
  d.table(sc);
  if (!c.plots.scalars.empty()) d.figure(c.plots.scalars, "Scalar experiments: (fitted - measured) / divisor; dashed lines at ±1, red: in conflict");
}

void add_curves(Document& d, const FitReportContent& c) {
  const auto& exps = c.record.experiments;
  if (std::all_of(exps.begin(), exps.end(), [](const FitRecord::Experiment& x) { return is_scalar(x); })) return;
  d.heading(2, "Curves: data and fit", "curves");
  for (std::size_t i = 0; i < exps.size(); ++i) {
    const auto& x = exps[i];
    const auto& v = c.verdict.experiments[i];
    if (is_scalar(x)) continue;
    d.heading(3, x.name);
    if (!c.data[i].ok) {
      d.para({{"No data: " + data_file_of(x) + " could not be read."}});
      continue;
    }
    std::string line = std::to_string(c.data[i].measured.size()) + " points; " + v.text;
    if (v.sign_changes >= 0) {
      line += "; the residual changes sign " + std::to_string(v.sign_changes) + " times (about " + format_fixed(v.expected_sign_changes, 0) +
              " expected for independent noise)";
    }
    d.para({{line + "."}});
    const std::string fit_plot = link_at(c.plots.fit, i), residual_plot = link_at(c.plots.residuals, i);
    if (!fit_plot.empty()) d.figure(fit_plot, x.name + ": measured points, initial (dashed) and fitted simulation");
    if (!residual_plot.empty()) {
      d.figure(residual_plot, x.name + ": residuals (fitted - measured) / divisor" +
                                  std::string(v.conditioning == Conditioning::noise ? "; dashed lines at ±1 σ" : ""));
    }
  }
}

void add_convergence(Document& d, const FitReportContent& c) {
  const auto& history = c.record.cost_history;
  d.heading(2, "Convergence", "convergence");
  if (!c.plots.convergence.empty()) d.figure(c.plots.convergence, "Cost per iteration (log scale)");
  if (!history.empty() && history.size() <= 40) {
    Table h;
    h.id = "convergence";
    h.header = {"iteration", "cost"};
    h.right = {true, true};
    for (std::size_t i = 0; i < history.size(); ++i) h.rows.push_back({cell(std::to_string(i)), cell(fmt(history[i], 8))});
    d.table(h);
  } else if (history.empty()) {
    d.para({{"No cost history in fit.json."}});
  } else {
    d.para({{std::to_string(history.size()) + " iterations; first cost " + fmt(history.front()) + ", last " + fmt(history.back()) + "."}});
  }
}

void add_correlation(Document& d, const FitRecord& rec) {
  const auto& names = rec.correlation.names;
  const auto& m = rec.correlation.matrix;
  d.heading(2, "Correlation of the parameters", "correlation");
  if (m.empty() || m.size() != names.size()) {
    d.para({{"No correlation matrix in fit.json."}});
    return;
  }
  Table t;
  t.id = "correlation";
  t.header.push_back("");
  t.right.push_back(false);
  for (const auto& n : names) {
    t.header.push_back(n);
    t.right.push_back(true);
  }
  for (std::size_t a = 0; a < m.size(); ++a) {
    std::vector<Cell> r{cell(names[a])};
    for (std::size_t b = 0; b < m[a].size(); ++b) {
      const double v = m[a][b];
      Cell x = cell(format_fixed(v, 3));
      if (a == b) x.style = CellStyle::diagonal;
      else if (std::isfinite(v) && std::abs(v) >= verdict_limits::kCorrWarn) x.style = CellStyle::bad;
      else if (std::isfinite(v) && std::abs(v) >= verdict_limits::kCorrNote) x.style = CellStyle::warn;
      else x.shade = std::abs(v);  // the strength of the correlation, whatever its sign
      r.push_back(x);
    }
    t.rows.push_back(r);
  }
  d.table(t);
  d.para({{"|r| near 1: the two parameters compensate each other; the data fix a combination of them, not each one."}});
}

void add_singular_values(Document& d, const FitRecord& rec) {
  const auto& sv = rec.uncertainty.singular_values_scaled;
  d.heading(2, "Singular values", "singular-values");
  if (sv.empty()) {
    d.para({{"No singular values in fit.json."}});
    return;
  }
  Table t;
  t.id = "singular-values";
  t.header = {"#", "singular value", "relative to the largest"};
  t.right = {true, true, true};
  double mx = 0.0;
  for (double v : sv) {
    if (std::isfinite(v)) mx = std::max(mx, v);
  }
  for (std::size_t i = 0; i < sv.size(); ++i) {
    const double rel = mx > 0 ? sv[i] / mx : kNaN;
    t.rows.push_back({cell(std::to_string(i + 1)), cell(fmt(sv[i], 4)), cell(fmt(rel, 3), bad_if(std::isfinite(rel) && rel < 1e-8))});
  }
  d.table(t);
  d.para({{"Singular values of the Jacobian scaled by the parameter magnitudes (relative sensitivities). Condition number " +
           fmt(rec.uncertainty.condition_number, 4) + ". A singular value near zero marks a parameter combination the experiments cannot see."}});
  if (std::isfinite(rec.uncertainty.relative_offset))
    d.para({{"Relative offset at the solution " + fmt(rec.uncertainty.relative_offset, 3) +
             ": a Gauss-Newton step from the solution would move no parameter inside its bounds by more than the square root of their number times this, in standard errors."}});
}

void add_files(Document& d, const FitReportContent& c) {
  d.heading(2, "Files", "files");
  const std::string card = fitted_card_file(c.record);
  const bool usable = card == "card.toml";
  std::vector<Inline> files{{{card, false, true, card}, {usable ? ": the fitted material card" : ": the fitted material card of a fit that is NOT USABLE"}},
                            {{"fit.json", false, true, "fit.json"}, {": every number of this report"}}};
  for (const auto& x : c.exports) {
    std::string what = ": the fitted card for another FE code (approximations stated in its header)";
    if (x == "exports/notes.json") what = ": the notes of every exported deck";
    files.push_back({{x, false, true, x}, {what}});
  }
  for (const auto& x : c.record.experiments) {
    const std::string f = data_file_of(x);
    files.push_back({{f, false, true, path_inside(f).empty() ? "" : f}, {": measured and simulated values of " + x.name}});
  }
  if (c.plots_written) {
    files.push_back({{"plots/", false, true}, {": the plots (SVG); plots/src/ holds their gnuplot scripts and data (cd plots && gnuplot src/NAME.gp)"}});
  }
  d.list(files);
}

}  // namespace

Document fit_report_document(const FitReportContent& c) {
  Document d;
  d.title = "Fit report: " + (c.record.name.empty() ? std::string("(unnamed fit)") : c.record.name);
  add_intro_and_warnings(d, c);
  add_summary(d, c);
  add_parameters(d, c);
  add_card(d, c);
  add_experiments(d, c);
  add_per_experiment(d, c.record);
  add_information_shares(d, c.record);
  add_multistart(d, c.record);
  add_scalars(d, c);
  add_curves(d, c);
  add_convergence(d, c);
  add_forward_runs(d, c.record);
  add_correlation(d, c.record);
  add_singular_values(d, c.record);
  add_files(d, c);
  return d;
}

}  // namespace spifit::reports
