#include "reports/sweep_plots.hpp"

#include "reports/report_format.hpp"
#include "reports/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace spifit::reports {

bool sweep_log_x(const std::vector<double>& v) {
  if (v.empty()) return false;
  double lo = v.front(), hi = v.front();
  for (double x : v) {
    if (!(x > 0.0) || !std::isfinite(x)) return false;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return hi > 20.0 * lo;
}

namespace {
std::string unit_of(const std::vector<std::string>& units, std::size_t k) { return k < units.size() ? units[k] : std::string(); }
}  // namespace

std::string sweep_input_label(const SweepTable& t, std::size_t k) { return axis_label(t.inputs[k], unit_of(t.input_units, k), t.inputs[k]); }
std::string sweep_metric_label(const SweepTable& t, std::size_t k) { return axis_label(t.metrics[k], unit_of(t.metric_units, k), t.metrics[k]); }

std::vector<std::string> render_sweep_plots(const std::filesystem::path& dir, const SweepTable& t) {
  std::vector<std::string> warnings;
  const auto gnuplot = find_executable("gnuplot");
  if (gnuplot.empty()) return {"gnuplot not found: no sweep plots"};
  if (t.inputs.empty()) return warnings;
  const std::size_t n = t.input_values.size();
  // Group the points by the second input's value (first values of any further inputs only).
  std::map<double, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < n; ++i) {
    bool keep = true;
    for (std::size_t k = 2; k < t.inputs.size(); ++k) keep = keep && t.input_values[i][k] == t.input_values[0][k];
    if (!keep) continue;
    groups[t.inputs.size() > 1 ? t.input_values[i][1] : 0.0].push_back(i);
  }
  auto series_for = [&](auto value_of_point) {
    std::vector<Series> out;
    for (const auto& [v2, idx] : groups) {
      Series s;
      s.style = Series::Style::linespoints;
      if (t.inputs.size() > 1) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "%s = %.6g", t.inputs[1].c_str(), v2);
        s.title = buf;
        const std::string unit = unit_of(t.input_units, 1);
        if (!unit.empty() && unit != "-") s.title += " " + unit;
      } else {
        s.title = "";
      }
      for (std::size_t i : idx) {
        s.x.push_back(t.input_values[i][0]);
        s.y.push_back(value_of_point(i));
      }
      out.push_back(s);
    }
    return out;
  };
  std::vector<double> first;
  for (const auto& v : t.input_values) first.push_back(v[0]);
  const bool log_x = sweep_log_x(first);
  const auto plots = dir / "plots";
  for (std::size_t m = 0; m < t.metrics.size(); ++m) {
    PlotSpec p;
    p.stem = "sweep_" + t.metrics[m];
    p.title = t.metrics[m] + " vs " + t.inputs[0];
    p.xlabel = sweep_input_label(t, 0);
    p.ylabel = sweep_metric_label(t, m);
    p.key = t.inputs.size() > 1;
    p.log_x = log_x;
    p.series = series_for([&](std::size_t i) { return t.ok[i] ? t.metric_values[i][m] : NAN; });
    const auto r = render_plot(gnuplot, plots, p);
    if (!r.ok) warnings.push_back("plot " + p.stem + ": " + r.message);
  }
  PlotSpec w;
  w.stem = "sweep_wall_seconds";
  w.title = "run time per point";
  w.xlabel = sweep_input_label(t, 0);
  w.ylabel = "wall time [s]";
  w.key = t.inputs.size() > 1;
  w.log_x = log_x;
  w.series = series_for([&](std::size_t i) { return t.wall_seconds[i]; });
  const auto r = render_plot(gnuplot, plots, w);
  if (!r.ok) warnings.push_back("plot " + w.stem + ": " + r.message);
  return warnings;
}

}  // namespace spifit::reports
