#pragma once
// The report of an FE run's output directory (indent, indent_line, line, cone, vwall):
// DIR/report.md and DIR/report.html with SVG plots under DIR/plots/ (gnuplot, as the fit
// report): the run's summary and status, the tool force against tool-tip depth (indent) or
// tool travel, contour means (cone), the sections' shape and thickness, the energy account,
// Newton iterations per increment, and where the time went. Works on a partial directory (a
// run still going or killed): it shows what the files hold so far.
#include "reports/fit_report.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

struct RunReportSummary {
  std::filesystem::path markdown, html;
  std::vector<std::filesystem::path> plots;
  std::vector<std::string> warnings;  // problems of rendering (gnuplot, unreadable files)
};

// True when DIR/summary.json describes an FE scene run (its "kind" is one of the FE scenes).
bool is_fe_run_directory(const std::filesystem::path& dir);

// Throws io::InputError when DIR has no readable summary.json of an FE run.
RunReportSummary render_run_report(const std::filesystem::path& dir, const ReportOptions& options = {});

}  // namespace spifit::reports
