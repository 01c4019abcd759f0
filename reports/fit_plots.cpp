#include "reports/fit_plots.hpp"

#include "reports/report_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spifit::reports {

using inverse::FitRecord;

namespace {

std::string curve_stem(int index, const FitRecord::Experiment& e) {
  char num[16];
  std::snprintf(num, sizeof num, "%02d", index);
  return std::string(num) + "_" + safe_file_stem(e.name);
}

// The quantities of FE experiments in words, by kind (the names are fit-file keys: y = "fz").
struct Words {
  const char* kind;
  const char* name;
  const char* words;
};
constexpr Words kWords[] = {
    {"force_curve", "depth", "tool-tip depth"}, {"force_curve", "travel", "tool travel"}, {"force_curve", "time", "time"},
    {"force_curve", "fx", "Fx"}, {"force_curve", "fy", "Fy"}, {"force_curve", "fz", "Fz"}, {"force_curve", "fr", "Fr"},
    {"force_curve", "ftheta", "Fθ"},
    {"section", "x", "x"}, {"section", "x0", "initial x"}, {"section", "z", "z"}, {"section", "thickness", "thickness"},
    {"contour_means", "contour", "contour"}, {"contour_means", "fx", "contour mean Fx"}, {"contour_means", "fy", "contour mean Fy"},
    {"contour_means", "fz", "contour mean Fz"}, {"contour_means", "fr", "contour mean Fr"}, {"contour_means", "ftheta", "contour mean Fθ"},
    {"contour_means", "ftheta_over_fz", "contour mean Fθ / Fz"}, {"contour_means", "fr_over_fz", "contour mean Fr / Fz"},
};

std::string x_label(const FitRecord::Experiment& e, const ExperimentData& d) { return experiment_axis_label(e, true, d.x_column); }

}  // namespace

std::string experiment_axis_label(const FitRecord::Experiment& e, bool abscissa, const std::string& fallback) {
  const std::string& name = abscissa ? e.x : e.y;
  std::string shown = name.empty() ? fallback : name;
  for (const Words& w : kWords) {
    if (e.kind == w.kind && name == w.name) shown = w.words;
  }
  const std::string& words = abscissa ? e.x_words : e.y_words;
  if (!words.empty()) shown = words;
  return axis_label(shown, abscissa ? e.x_unit : e.y_unit, abscissa ? "x" : "y");
}

namespace {

// The link of a rendered image, relative to the report ("plots/NAME.svg"), or empty.
std::string render(PlotSession& session, const PlotSpec& spec) {
  const auto file = session.render(spec);
  return file.empty() ? std::string() : "plots/" + file.filename().string();
}

}  // namespace

PlotSpec curve_fit_plot(int index, const FitRecord::Experiment& e, const ExperimentData& d) {
  PlotSpec f;
  f.stem = curve_stem(index, e) + "_fit";
  f.title = e.name + ": data and simulation";
  f.xlabel = x_label(e, d);
  f.ylabel = experiment_axis_label(e, false, "");
  f.series.push_back({"measured", d.x, d.measured, Series::Style::points, ""});
  f.series.push_back({"initial simulation", d.x, d.initial, Series::Style::dashed_line, ""});
  f.series.push_back({"fitted simulation", d.x, d.fitted, Series::Style::line, "#d62728"});
  // Keep the data readable when the starting guess is far off: clip it to 3x the data span.
  double lo = INFINITY, hi = -INFINITY, ilo = INFINITY, ihi = -INFINITY;
  for (std::size_t i = 0; i < d.measured.size(); ++i) {
    for (double v : {d.measured[i], d.fitted[i]}) {
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (std::isfinite(d.initial[i])) ilo = std::min(ilo, d.initial[i]), ihi = std::max(ihi, d.initial[i]);
  }
  if (hi > lo && ihi >= ilo && std::max(hi, ihi) - std::min(lo, ilo) > 3.0 * (hi - lo)) {
    f.has_yrange = true;
    f.ymin = lo - 0.5 * (hi - lo);
    f.ymax = hi + 0.5 * (hi - lo);
    f.series[1].title = "initial simulation (clipped)";
  }
  return f;
}

PlotSpec curve_residual_plot(int index, const FitRecord::Experiment& e, const ExperimentData& d, const ExperimentVerdict& v) {
  PlotSpec r;
  r.stem = curve_stem(index, e) + "_residuals";
  const bool sigma = v.conditioning == Conditioning::noise;
  r.title = e.name + ": residuals of the fit";
  r.xlabel = x_label(e, d);
  r.ylabel = sigma ? "(fitted - measured) / noise σ" : "(fitted - measured) / scale";
  r.key = false;
  std::vector<double> res(d.measured.size());
  for (std::size_t i = 0; i < res.size(); ++i) res[i] = (d.fitted[i] - d.measured[i]) / e.scale;
  r.series.push_back({"fitted - measured", d.x, res, Series::Style::linespoints, "#1f77b4"});
  r.hlines.push_back({0.0, false});
  if (sigma) {
    r.hlines.push_back({1.0, true});
    r.hlines.push_back({-1.0, true});
    // The lines at +-1 sigma stay in view: residuals far below the noise look small.
    double m = 1.2;
    for (double x : res) {
      if (std::isfinite(x)) m = std::max(m, 1.15 * std::abs(x));
    }
    r.has_yrange = true;
    r.ymin = -m;
    r.ymax = m;
  }
  return r;
}

PlotSpec scalar_plot(const FitRecord& rec, const std::vector<ExperimentData>& data, const FitVerdict& verdict) {
  PlotSpec s;
  s.stem = "scalars";
  s.title = "scalar experiments: (fitted - measured) / scale";
  s.xlabel = "experiment";
  s.ylabel = "residual / scale (σ when noise is given)";
  Series bars{"fitted - measured", {}, {}, Series::Style::bars, ""};
  Series conflicts{"in conflict", {}, {}, Series::Style::bars, "#d62728"};
  bool any_noise = false;
  for (std::size_t i = 0; i < rec.experiments.size(); ++i) {
    const auto& e = rec.experiments[i];
    if (!is_scalar(e) || !data[i].ok) continue;
    Series& into = verdict.experiments[i].level == 2 ? conflicts : bars;
    into.x.push_back(static_cast<double>(s.categories.size()));
    into.y.push_back((data[i].fitted[0] - data[i].measured[0]) / e.scale);
    s.categories.push_back(e.name);
    any_noise = any_noise || verdict.experiments[i].conditioning == Conditioning::noise;
  }
  if (s.categories.empty()) return s;
  s.series.push_back(bars);
  s.series.push_back(conflicts);
  s.key = false;
  s.hlines.push_back({0.0, false});
  if (any_noise) {
    s.hlines.push_back({1.0, true});
    s.hlines.push_back({-1.0, true});
  }
  double m = 1.2;
  for (const auto* b : {&bars, &conflicts}) {
    for (double v : b->y) {
      if (std::isfinite(v)) m = std::max(m, 1.15 * std::abs(v));
    }
  }
  s.has_yrange = true;
  s.ymin = -m;
  s.ymax = m;
  s.width = std::max(520, std::min(1000, 160 + 90 * static_cast<int>(s.categories.size())));
  return s;
}

PlotSpec convergence_plot(const FitRecord& rec) {
  PlotSpec c;
  c.stem = "convergence";
  c.title = "convergence: cost per iteration";
  const bool ceres = rec.algorithm == "levenberg_marquardt" || rec.algorithm == "dogleg" || rec.algorithm.empty();
  c.xlabel = ceres ? "iteration" : "improvement (objective evaluations that lowered the cost)";
  c.ylabel = "cost (log scale)";
  c.log_y = true;
  c.key = false;
  c.integer_x = true;
  Series h{"cost", {}, rec.cost_history, Series::Style::linespoints, "#2ca02c"};
  for (std::size_t i = 0; i < rec.cost_history.size(); ++i) h.x.push_back(static_cast<double>(i));
  c.series.push_back(h);
  return c;
}

FitPlots render_fit_plots(const FitRecord& rec, const std::vector<ExperimentData>& data, const FitVerdict& verdict, PlotSession& session) {
  FitPlots out;
  out.fit.resize(rec.experiments.size());
  out.residuals.resize(rec.experiments.size());
  for (std::size_t i = 0; i < rec.experiments.size(); ++i) {
    const auto& e = rec.experiments[i];
    if (is_scalar(e) || !data[i].ok) continue;
    const int index = static_cast<int>(i) + 1;
    out.fit[i] = render(session, curve_fit_plot(index, e, data[i]));
    out.residuals[i] = render(session, curve_residual_plot(index, e, data[i], verdict.experiments[i]));
  }
  const PlotSpec s = scalar_plot(rec, data, verdict);
  if (!s.categories.empty()) out.scalars = render(session, s);
  if (!rec.cost_history.empty()) out.convergence = render(session, convergence_plot(rec));
  return out;
}

}  // namespace spifit::reports
