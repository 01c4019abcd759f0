#pragma once
// Plots of a sweep (DIR/plots/sweep_*.svg): each metric against the first input, one series
// per value of the second input when there are two or more inputs (further inputs at their
// first value), and the run time per point. The x axis is logarithmic when the first input's
// values are all > 0 and span more than a factor 20 (e.g. a contact penalty 1e1..1e7).
#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

struct SweepTable {
  std::vector<std::string> inputs, metrics;
  std::vector<std::string> input_units, metric_units;  // per input / metric ("" or "-": none; may be empty)
  std::vector<std::vector<double>> input_values;   // per point
  std::vector<std::vector<double>> metric_values;  // per point (NaN: not available)
  std::vector<double> wall_seconds;
  std::vector<bool> ok;
};

// True when the first input's values call for a logarithmic x axis (all > 0, max/min > 20).
bool sweep_log_x(const std::vector<double>& first_input_values);

// "NAME [UNIT]" of input or metric k (no brackets without a unit).
std::string sweep_input_label(const SweepTable& t, std::size_t k);
std::string sweep_metric_label(const SweepTable& t, std::size_t k);

// Returns warnings (gnuplot missing or failing); never throws for plotting problems.
std::vector<std::string> render_sweep_plots(const std::filesystem::path& dir, const SweepTable& table);

}  // namespace spifit::reports
