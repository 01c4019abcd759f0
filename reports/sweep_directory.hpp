#pragma once
// Re-rendering the report of a sweep's output directory (`spifit report DIR`): the table is read
// back from DIR/sweep.csv, which inputs and metrics it holds (with units) and why points failed
// from DIR/summary.json.
#include "reports/sweep_report.hpp"

#include <filesystem>

namespace spifit::reports {

// Whether DIR/summary.json says it is a sweep's output directory.
bool is_sweep_directory(const std::filesystem::path& dir);

// DIR/report.md, report.html and plots/ from what the sweep wrote. A summary without the table's
// description (an older spifit, or a sweep still running) or a damaged sweep.csv is an
// io::InputError naming the file and key or line.
SweepReportSummary rerender_sweep_report(const std::filesystem::path& dir, bool plots = true);

}  // namespace spifit::reports
