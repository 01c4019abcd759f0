#pragma once
// A human report of a fit: reads what `spifit fit --out DIR` wrote (DIR/fit.json, or the record
// handed over in memory, and DIR/experiments/NAME.csv) and writes DIR/report.md, DIR/report.html (self-contained, inline
// CSS, images referenced as plots/NAME.svg) and DIR/plots/*.svg made with gnuplot
// (scripts and data kept under DIR/plots/src/). Contents and rules: docs/guide/reading-reports.md.
#include "inverse/fit/fit_record.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

struct ReportOptions {
  bool plots = true;                // render DIR/plots/*.svg with gnuplot
  std::string gnuplot = "gnuplot";  // program name (looked up on PATH) or path to it
};

struct ReportSummary {
  std::filesystem::path markdown, html;      // DIR/report.md, DIR/report.html
  std::vector<std::filesystem::path> plots;  // the SVG files written (those the report shows)
  // Problems of the FIT, in plain words, as the report's "Warnings" box shows them: fit.json's
  // own warnings plus those found here (experiments in conflict with the model, parameters at
  // a bound, near-perfect correlations, a fit that did not converge).
  std::vector<std::string> findings;
  std::vector<std::string> notes;  // the report's yellow box (fit-file remarks, mild findings)
  // Problems of RENDERING (gnuplot missing or failing, an unreadable experiments/*.csv): the
  // report is still written, with fewer plots. Meant for stderr.
  std::vector<std::string> warnings;
};

// Throws io::InputError naming DIR/fit.json when it is missing or not a valid fit.json;
// std::runtime_error when the report files cannot be written. Never fails because of gnuplot.
ReportSummary render_fit_report(const std::filesystem::path& dir, const ReportOptions& options = {});
// The same for the fit that has just written DIR, from its record in memory (the same record
// as DIR/fit.json holds; `spifit fit` does not read back what it wrote).
ReportSummary render_fit_report_from_record(const std::filesystem::path& dir, inverse::FitRecord record, const ReportOptions& options = {});

}  // namespace spifit::reports
