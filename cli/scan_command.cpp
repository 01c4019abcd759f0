// `spifit scan`: a laser-scan point cloud averaged into a cross section with a 90 % band
// (inverse/experiments/scan_section.hpp; thesis §8.2.1, footnotes 4 and 5).
#include "cli/commands.hpp"
#include "cli/cli_errors.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"
#include "inverse/experiments/scan_section.hpp"
#include "reports/plot.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <map>
#include <stdexcept>

namespace spifit::cli {
namespace {

// "FIELD = VALUE: message" (ScanSectionOptions::validate) as an InputError on the option.
[[noreturn]] void option_error(const std::string& text) {
  static const std::map<std::string, std::string> option{{"bin", "--bin"}, {"origin_z", "--origin-z"}, {"min_points", "--min-points"},
                                                          {"band", "--band"}, {"shift_thickness", "--shift-by-half-thickness"}};
  const std::size_t eq = text.find(" = "), colon = text.find(": ", eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || colon == std::string::npos) throw io::InputError("", "", "", text);
  const std::string field = text.substr(0, eq);
  const auto it = option.find(field);
  throw io::InputError("", it == option.end() ? field : it->second, text.substr(eq + 3, colon - eq - 3), text.substr(colon + 2));
}

std::vector<std::string> section_plot(const std::filesystem::path& dir, const inverse::ScanSection& s, const std::string& cloud) {
  const auto gnuplot = reports::find_executable("gnuplot");
  if (gnuplot.empty()) return {"gnuplot not found: no plot"};
  reports::PlotSpec p;
  p.stem = "section";
  p.title = "scan section of " + std::filesystem::path(cloud).filename().string() + " (" + std::to_string(s.points_used) + " points)";
  p.xlabel = "r [mm]";
  p.ylabel = "z [mm]";
  reports::Series mean{"mean", {}, {}, reports::Series::Style::linespoints, ""};
  reports::Series low{"band (5 %)", {}, {}, reports::Series::Style::dashed_line, ""};
  reports::Series high{"band (95 %)", {}, {}, reports::Series::Style::dashed_line, ""};
  for (const auto& b : s.bins) {
    mean.x.push_back(b.mean.x());
    mean.y.push_back(b.mean.y());
    low.x.push_back(b.band_low.x());
    low.y.push_back(b.band_low.y());
    high.x.push_back(b.band_high.x());
    high.y.push_back(b.band_high.y());
  }
  p.series = {mean, low, high};
  const auto r = reports::render_plot(gnuplot, dir / "plots", p);
  if (!r.ok) return {"plot section: " + r.message};
  return {};
}

}  // namespace

void add_scan_command(CLI::App& app, const GlobalOptions& g, int& exit_code) {
  struct Opts {
    std::string cloud, out, by = "radius", shift_along = "vertical";
    double shift = 0.0;
    bool force = false, no_plot = false;
    inverse::ScanSectionOptions scan;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("scan", "Average a laser-scan point cloud (CSV x, y, z) into a cross section with a 90 % band "
                                         "(thesis §8.2.1): DIR/section.csv, DIR/summary.json, DIR/plots/section.svg");
  cmd->add_option("CLOUD", o->cloud, "point cloud: CSV with a header naming columns x, y, z [mm], the cone axis = z axis")->required();
  cmd->add_option("--out", o->out, "output directory")->required();
  cmd->add_option("--bin", o->scan.bin, "bin width: mm of radius (--by radius) or degrees (--by angle); default 0.5");
  cmd->add_option("--by", o->by, "radius (default) | angle (thesis footnote 4: angle from +z of the line from the origin)");
  cmd->add_option("--origin-z", o->scan.origin_z, "--by angle: the origin (0, 0, Z); default 0");
  cmd->add_option("--min-points", o->scan.min_points, "bins with fewer points are left out; default 5");
  cmd->add_option("--band", o->scan.band, "fraction of the points inside the band (empirical quantiles); default 0.90");
  cmd->add_option("--shift-by-half-thickness", o->shift, "shift the section by T/2 towards the tool side (the outer surface to the mid-surface)");
  cmd->add_option("--shift-along", o->shift_along, "vertical (default; thesis footnote 5) | normal (along the section's normal)");
  cmd->add_flag("--no-plot", o->no_plot, "skip the gnuplot plot");
  cmd->add_flag("--force", o->force, "replace an existing spifit output directory");
  cmd->callback([o, &g, &exit_code] {
    auto opts = o->scan;
    if (o->by == "radius") opts.binning = inverse::ScanBinning::radius;
    else if (o->by == "angle") opts.binning = inverse::ScanBinning::angle;
    else throw io::InputError("", "--by", o->by, "unknown binning (radius, angle)");
    if (o->shift_along != "vertical" && o->shift_along != "normal") throw io::InputError("", "--shift-along", o->shift_along, "unknown direction (vertical, normal)");
    if (o->shift != 0.0) {
      opts.shift = o->shift_along == "normal" ? inverse::ScanShift::normal : inverse::ScanShift::vertical;
      opts.shift_thickness = o->shift;
    }
    if (const std::string err = opts.validate(); !err.empty()) option_error(err);
    // Input errors (file, line, value) before the output directory is touched.
    const auto cloud = inverse::read_scan_cloud(o->cloud);
    inverse::ScanSection s;
    try {
      s = inverse::average_scan_section(cloud, opts);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(o->cloud, "--min-points", std::to_string(opts.min_points), e.what());
    }
    const auto dir = prepare_output(o->out, o->force, {o->cloud}, g.quiet);
    const bool by_angle = opts.binning == inverse::ScanBinning::angle;
    char head[600];
    std::snprintf(head, sizeof head,
                  "# spifit scan section of %s: %d points, %d used in %zu bins of %g %s by %s (%d bins with fewer than %d points left out)\n"
                  "# r, z: mean of the bin's points; band: %g %% of the points (empirical quantiles) of %s; std: their standard deviation\n"
                  "# shift: %s\n",
                  o->cloud.c_str(), s.points, s.points_used, s.bins.size(), opts.bin, by_angle ? "deg" : "mm", by_angle ? "angle from +z" : "radius",
                  s.bins_left_out, opts.min_points, 100.0 * opts.band, by_angle ? "the distance from the origin, along the ray" : "z",
                  opts.shift == inverse::ScanShift::none ? "none"
                  : opts.shift == inverse::ScanShift::vertical ? ("+T/2 in z, T = " + io::format_number(opts.shift_thickness)).c_str()
                                                               : ("T/2 along the section normal, T = " + io::format_number(opts.shift_thickness)).c_str());
    dir.write_file("section.csv", head + inverse::scan_section_csv(s, opts));
    std::vector<std::string> warnings;
    if (!o->no_plot) warnings = section_plot(dir.path(), s, o->cloud);
    dir.record();  // plots/ in the manifest
    for (const auto& w : warnings)
      if (!g.quiet) std::cerr << "spifit: warning: " << w << "\n";
    nlohmann::json summary{{"status", "ok"},
                           {"kind", "scan"},
                           {"cloud", o->cloud},
                           {"points", s.points},
                           {"points_used", s.points_used},
                           {"bins", s.bins.size()},
                           {"bins_left_out", s.bins_left_out},
                           {"binning", o->by},
                           {"bin", opts.bin},
                           {"band", opts.band},
                           {"shift", opts.shift == inverse::ScanShift::none ? "none" : o->shift_along},
                           {"shift_thickness", opts.shift_thickness},
                           {"warnings", warnings}};
    dir.write_file("summary.json", summary.dump(2) + "\n");
    if (!g.quiet)
      std::printf("scan %s: %d points -> %zu bins (%d points used) -> %s/section.csv\n", o->cloud.c_str(), s.points, s.bins.size(),
                  s.points_used, o->out.c_str());
    exit_code = 0;
  });
}

}  // namespace spifit::cli
