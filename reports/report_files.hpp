#pragma once
// A report document written as DIR/report.md and DIR/report.html (atomically: a reader never
// sees half a file). Shared by the fit and the run reports.
#include "reports/report_document.hpp"

#include <filesystem>

namespace spifit::reports {

struct ReportFiles {
  std::filesystem::path markdown, html;
};

ReportFiles write_report_files(const std::filesystem::path& dir, const Document& doc);

}  // namespace spifit::reports
