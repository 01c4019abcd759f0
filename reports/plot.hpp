#pragma once
// Plots through gnuplot, safely: a plot is a PlotSpec (series of numbers plus labels); it is
// written as a data file and a script under PLOTS/src/ with names we generate, and gnuplot is
// started without a shell (fork + exec, argv ["gnuplot", "src/STEM.gp"], working directory
// PLOTS, stdin /dev/null, a time limit). User text (titles, experiment names, units) only
// ever appears inside single-quoted gnuplot strings (gnuplot_quote) with enhanced text off,
// so it cannot execute anything or break the script.
#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

// The program's full path: program itself when it contains '/', else the first executable
// match on PATH; empty when not found.
std::filesystem::path find_executable(const std::string& program);
// gnuplot for a report: its path, or empty with the warning that the report has no plots.
std::filesystem::path find_gnuplot(const std::string& program, std::vector<std::string>* warnings);

// A gnuplot single-quoted string literal: ' doubled, control characters replaced by spaces.
std::string gnuplot_quote(const std::string& text);

// Only [A-Za-z0-9_-] survive (others become '_'), at most 60 characters, never empty.
std::string safe_file_stem(const std::string& text);

struct Series {
  enum class Style { points, line, dashed_line, linespoints, bars };
  std::string title;
  std::vector<double> x, y;  // non-finite points are left out
  Style style = Style::line;
  std::string color;  // "#rrggbb"; empty: a default per style
};

struct HLine {
  double y = 0.0;
  bool dashed = false;
};

struct PlotSpec {
  std::string stem;                      // file names: STEM.svg, src/STEM.gp, src/STEM.dat (sanitised)
  std::string title, xlabel, ylabel;
  bool log_y = false;
  bool log_x = false;                    // logarithmic x axis (points with x <= 0 are left out)
  bool key = true;                       // legend (top left)
  bool key_outside = true;               // the legend right of the plot, off the data (false: inside, top left)
  bool integer_x = false;                // x tics at integers only (iterations)
  bool integer_y = false;                // y tics at integers only (Newton iterations, steps)
  std::vector<Series> series;
  std::vector<HLine> hlines;             // horizontal reference lines
  std::vector<std::string> categories;   // x tic labels at x = 0, 1, ... (bar plots)
  bool has_yrange = false;
  double ymin = 0.0, ymax = 0.0;
  int width = 760, height = 420;
};

enum class PlotFormat { svg, png };

struct PlotResult {
  bool ok = false;
  std::filesystem::path file;  // the image, when ok
  std::string message;         // why not, in one line
};

// The data file (one block per series, blocks separated by two blank lines) and the script.
std::string gnuplot_data(const PlotSpec& spec);
std::string gnuplot_script(const PlotSpec& spec, PlotFormat format, const std::string& output_name, const std::string& data_name);

struct GnuplotRun {
  bool ok = false;
  std::string message;  // exit status and the first lines gnuplot printed, when not ok
};

// Runs `gnuplot SCRIPT` (script relative to workdir) with workdir as working directory, no
// shell, stdin from /dev/null, stdout and stderr to workdir/LOG; killed after timeout_seconds.
GnuplotRun run_gnuplot(const std::filesystem::path& gnuplot, const std::filesystem::path& workdir, const std::string& script,
                       const std::string& log, double timeout_seconds = 60.0);

// Writes PLOTS/src/STEM.{dat,gp} and runs gnuplot to make PLOTS/STEM.svg (or .png). An old
// image of the same name is removed first, so a failure never leaves a stale plot behind.
PlotResult render_plot(const std::filesystem::path& gnuplot, const std::filesystem::path& plots_dir, const PlotSpec& spec,
                       PlotFormat format = PlotFormat::svg);

}  // namespace spifit::reports
