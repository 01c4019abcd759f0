// Assembles the fit report: reads the record (or takes it) and the data files, judges the fit, renders the
// plots, builds the document and writes it as Markdown and HTML.
#include "reports/fit_report.hpp"

#include "forward/io/input_error.hpp"
#include "inverse/fit/fit_record.hpp"
#include "reports/fit_document.hpp"
#include "reports/report_files.hpp"

#include <algorithm>
#include <utility>

namespace spifit::reports {

namespace fs = std::filesystem;

namespace {

inverse::FitRecord load_record(const fs::path& dir) {
  const fs::path path = dir / "fit.json";
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw io::InputError(path.string(), "", "", fs::exists(dir, ec) ? "no fit.json here: not an output directory of `spifit fit`"
                                                                    : "no such directory");
  }
  return inverse::read_fit_record(path);
}

// The plots, unless switched off; gnuplot missing or failing only costs plots (warnings).
void render_plots(const fs::path& dir, const ReportOptions& options, FitReportContent& c, ReportSummary& summary) {
  if (!options.plots) return;
  const fs::path gnuplot = find_gnuplot(options.gnuplot, &summary.warnings);
  if (gnuplot.empty()) return;
  PlotSession session(gnuplot, dir / "plots");
  std::string failure;
  try {
    c.plots = render_fit_plots(c.record, c.data, c.verdict, session);
  } catch (const std::exception& ex) {  // never fail the report because of a plot
    failure = std::string("plots: ") + ex.what();
  }
  summary.plots = session.images();
  summary.warnings.insert(summary.warnings.end(), session.warnings().begin(), session.warnings().end());
  if (!failure.empty()) summary.warnings.push_back(failure);
}

}  // namespace

ReportSummary render_fit_report(const fs::path& dir, const ReportOptions& options) { return render_fit_report_from_record(dir, load_record(dir), options); }

ReportSummary render_fit_report_from_record(const fs::path& dir, inverse::FitRecord record, const ReportOptions& options) {
  ReportSummary summary;
  FitReportContent c;
  c.record = std::move(record);
  c.data = read_fit_data(dir, c.record, &summary.warnings);
  c.verdict = judge_fit(c.record, c.data);
  for (const auto& f : c.verdict.findings) (f.level == 2 ? summary.findings : summary.notes).push_back(f.text);
  render_plots(dir, options, c, summary);
  c.plots_written = !summary.plots.empty();
  std::error_code ec;
  for (fs::directory_iterator it(dir / "exports", ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file()) c.exports.push_back("exports/" + it->path().filename().string());
  std::sort(c.exports.begin(), c.exports.end());
  try {
    const fs::path card = dir / fitted_card_file(c.record);
    if (fs::is_regular_file(card, ec)) c.card = material::load_material_card(card.string());
  } catch (const io::InputError& e) {
    summary.warnings.push_back(std::string("the fitted card cannot be read: ") + e.what());
  }

  const ReportFiles files = write_report_files(dir, fit_report_document(c));
  summary.markdown = files.markdown;
  summary.html = files.html;
  return summary;
}

}  // namespace spifit::reports
