#include "reports/sweep_report.hpp"

#include "reports/report_files.hpp"
#include "reports/report_format.hpp"

#include <cmath>

namespace spifit::reports {

namespace fs = std::filesystem;

SweepReportSummary render_sweep_report(const fs::path& dir, const std::string& title, const SweepTable& t,
                                       const std::vector<std::string>& messages, bool plots) {
  SweepReportSummary out;
  if (plots) out.warnings = render_sweep_plots(dir, t);
  Document d;
  d.title = "spifit sweep report: " + title;
  std::size_t failed = 0;
  double wall = 0.0;
  for (std::size_t i = 0; i < t.ok.size(); ++i) {
    failed += t.ok[i] ? 0 : 1;
    wall += t.wall_seconds[i];
  }
  if (failed > 0) {
    std::vector<Inline> items;
    for (std::size_t i = 0; i < t.ok.size(); ++i)
      if (!t.ok[i]) items.push_back({{"point " + std::to_string(i + 1) + ": " + (i < messages.size() ? messages[i] : std::string("failed"))}});
    d.callout(CalloutKind::warning, std::to_string(failed) + " of " + std::to_string(t.ok.size()) + " points failed", items);
  }
  Inline intro{{std::to_string(t.ok.size()) + " points, run time " + format_significant(wall, 4) + " s in all. Files: "},
               {"sweep.csv", false, true},
               {" (every point)"}};
  if (fs::is_directory(dir / "points")) intro.insert(intro.end(), {{", "}, {"points/", false, true}, {" (each FE point's outputs)"}});
  intro.push_back({"."});
  d.para(intro);
  d.heading(2, "Points", "points");
  Table tab;
  tab.id = "points";
  tab.header.push_back("point");
  for (std::size_t k = 0; k < t.inputs.size(); ++k) tab.header.push_back(sweep_input_label(t, k));
  for (std::size_t k = 0; k < t.metrics.size(); ++k) tab.header.push_back(sweep_metric_label(t, k));
  tab.header.push_back("wall time [s]");
  tab.right.assign(tab.header.size(), true);
  for (std::size_t i = 0; i < t.input_values.size(); ++i) {
    std::vector<Cell> row{cell(std::to_string(i + 1), t.ok[i] ? CellStyle::plain : CellStyle::bad)};
    for (double v : t.input_values[i]) row.push_back(cell(format_significant(v, 6)));
    for (double v : t.metric_values[i]) row.push_back(cell(t.ok[i] ? format_significant(v, 6) : "failed", t.ok[i] ? CellStyle::plain : CellStyle::bad));
    row.push_back(cell(format_significant(t.wall_seconds[i], 3)));
    tab.rows.push_back(std::move(row));
  }
  d.table(tab);
  bool heading = false;
  auto figure = [&](const std::string& stem, const std::string& caption) {
    if (!fs::exists(dir / "plots" / (stem + ".svg"))) return;
    if (!heading) d.heading(2, "Plots", "plots");
    heading = true;
    d.figure("plots/" + stem + ".svg", caption);
  };
  if (!t.inputs.empty()) {
    for (std::size_t m = 0; m < t.metrics.size(); ++m)
      figure("sweep_" + t.metrics[m], sweep_metric_label(t, m) + " against " + sweep_input_label(t, 0));
    figure("sweep_wall_seconds", "Run time of each point");
  }
  const ReportFiles files = write_report_files(dir, d);
  out.markdown = files.markdown;
  out.html = files.html;
  return out;
}

}  // namespace spifit::reports
