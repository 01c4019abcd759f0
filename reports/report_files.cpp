#include "reports/report_files.hpp"

#include "forward/io/atomic_file.hpp"
#include "reports/html_writer.hpp"
#include "reports/markdown_writer.hpp"

namespace spifit::reports {

ReportFiles write_report_files(const std::filesystem::path& dir, const Document& doc) {
  ReportFiles f{dir / "report.md", dir / "report.html"};
  io::write_file_atomic(f.markdown, to_markdown(doc));
  io::write_file_atomic(f.html, to_html(doc));
  return f;
}

}  // namespace spifit::reports
