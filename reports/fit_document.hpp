#pragma once
// The fit report as a Document (report_document.hpp): warnings, summary, parameters,
// experiments, curves, convergence, forward runs, correlation, singular values and files, in the order
// docs/guide/reading-reports.md lists them.
#include "inverse/fit/fit_record.hpp"
#include "reports/experiment_data.hpp"
#include "reports/fit_plots.hpp"
#include "reports/fit_verdict.hpp"
#include "reports/report_document.hpp"

#include "forward/material/material_card.hpp"

#include <optional>
#include <vector>

namespace spifit::reports {

// Everything the report shows; the per-experiment vectors follow record.experiments.
struct FitReportContent {
  inverse::FitRecord record;
  std::vector<ExperimentData> data;
  FitVerdict verdict;
  FitPlots plots;
  bool plots_written = false;  // any image under plots/ (the Files section names the folder)
  std::vector<std::string> exports;  // the files under exports/ (relative to DIR, sorted)
  std::optional<material::MaterialCard> card;  // the fitted card as written (absent: not readable)
};

Document fit_report_document(const FitReportContent& content);

}  // namespace spifit::reports
