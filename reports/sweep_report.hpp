#pragma once
// The report of a sweep's output directory: DIR/report.md and DIR/report.html with the points
// (inputs and metrics with their units, run time, failures) and the sweep's plots
// (sweep_plots.hpp) under DIR/plots/.
#include "reports/sweep_plots.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

struct SweepReportSummary {
  std::filesystem::path markdown, html;
  std::vector<std::string> warnings;  // problems of rendering (gnuplot missing or failing)
};

// title: the sweep's name; messages: why each failed point failed (empty for those that ran).
SweepReportSummary render_sweep_report(const std::filesystem::path& dir, const std::string& title, const SweepTable& table,
                                       const std::vector<std::string>& messages, bool plots = true);

}  // namespace spifit::reports
