// `spifit report`: re-renders the report of a fit's, a sweep's or an FE run's directory (reports/).
#include "cli/commands.hpp"

#include "forward/io/output_directory.hpp"
#include "inverse/sweeps/sweep.hpp"
#include "reports/fit_report.hpp"
#include "reports/run_report.hpp"
#include "reports/sweep_directory.hpp"
#include "reports/sweep_report.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace spifit::cli {

void add_report_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts { std::string dir; bool no_plots = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("report", "Re-render report.md, report.html and plots of a fit's, a sweep's or an FE run's output directory (also a partial run)");
  cmd->add_option("DIR", o->dir, "output directory of spifit fit, spifit sweep or spifit run (indent, indent_line, line, cone)")->required();
  cmd->add_flag("--no-plots", o->no_plots, "skip the gnuplot plots");
  cmd->callback([o, &g, &exit_code] {
    reports::ReportOptions ro;
    ro.plots = !o->no_plots;
    // Opened before rendering: what is there and not in its manifest stays out of it. No lock:
    // a run still going (or killed) is reported as far as it got; the report's files are written
    // atomically and the run's own report at its end replaces them.
    std::optional<io::OutputDirectory> dir;
    if (std::filesystem::is_directory(o->dir)) dir = io::OutputDirectory::existing(o->dir, io::OutputDirectory::Locking::none);
    if (!std::filesystem::exists(std::filesystem::path(o->dir) / "fit.json") && reports::is_sweep_directory(o->dir)) {
      const auto r = reports::rerender_sweep_report(o->dir, ro.plots);
      if (dir) dir->record();
      for (const auto& w : r.warnings) std::cerr << "spifit: warning: " << w << "\n";
      if (!g.quiet) std::cout << "wrote " << r.markdown.string() << " and " << r.html.string() << "\n";
      exit_code = 0;
      return;
    }
    if (!std::filesystem::exists(std::filesystem::path(o->dir) / "fit.json") && reports::is_fe_run_directory(o->dir)) {
      const auto r = reports::render_run_report(o->dir, ro);
      if (dir) dir->record();
      for (const auto& w : r.warnings) std::cerr << "spifit: warning: " << w << "\n";
      if (!g.quiet) std::cout << "wrote " << r.markdown.string() << ", " << r.html.string() << " and " << r.plots.size() << " plots\n";
      exit_code = 0;
      return;
    }
    const auto r = reports::render_fit_report(o->dir, ro);
    if (dir) dir->record();  // plots/ when the fit had none
    for (const auto& w : r.warnings) std::cerr << "spifit: warning: " << w << "\n";
    if (!g.quiet) std::cout << "wrote " << r.markdown.string() << ", " << r.html.string() << " and " << r.plots.size() << " plots\n";
    exit_code = 0;
  });
}

}  // namespace spifit::cli
