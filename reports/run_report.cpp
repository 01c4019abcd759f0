// Assembles the report of an FE run: reads summary.json and the CSV files the run wrote,
// renders the plots, builds the document and writes it as Markdown and HTML.
#include "reports/run_report.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "reports/output_table.hpp"
#include "reports/plot_session.hpp"
#include "reports/report_files.hpp"
#include "reports/report_document.hpp"
#include "reports/report_format.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace spifit::reports {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::optional<json> read_summary(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir / "summary.json", ec)) return std::nullopt;
  try {
    return json::parse(io::read_text_file((dir / "summary.json").string()));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The scene kind of summary.json runs FE with a tool (the registry's SceneKind::fe_run).
bool is_fe_kind(const json& s) {
  const scene::SceneKind* k = scene::find_scene_kind(s.value("kind", ""));
  return k && k->fe_run;
}

std::string fe_kind_names() {
  std::string s;
  for (const auto& k : scene::scene_kinds())
    if (k.fe_run) s += (s.empty() ? "" : ", ") + k.name;
  return s;
}

double number_at(const json& j, const char* key, double fallback = NAN) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

std::string force_text(const json& j) {
  if (!j.is_array() || j.size() != 3) return "n/a";
  return "(" + format_fixed(j[0].get<double>(), 1) + ", " + format_fixed(j[1].get<double>(), 1) + ", " + format_fixed(j[2].get<double>(), 1) +
         ") N";
}

// What the report shows of one run, and the plots it rendered.
struct RunContent {
  json summary;
  OutputTable force, energies, contours, cone_sections, sensitivities;
  std::vector<std::pair<std::string, OutputTable>> sections;  // forming: path point, section
  std::vector<std::pair<std::string, std::string>> figures;   // image, caption
};

// The force log has the polar components of an axisymmetric part (Fr, Ftheta at the tool's angle).
bool has_polar_force(const RunContent& c) { return !c.force.column("Fr").empty(); }

// The tool only went up and down (an indent): the force is plotted against the tool-tip depth.
bool tool_moved_vertically_only(const RunContent& c) {
  const std::vector<double> x = c.force.column("tool_x"), y = c.force.column("tool_y");
  if (x.empty() || y.empty()) return false;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i] != x[0] || y[i] != y[0]) return false;
  return true;
}

// Tool travel [mm] of each force.csv row: time x feed (every FE scene writes time = travel / feed).
std::vector<double> travel(const RunContent& c) {
  std::vector<double> t = c.force.column("time");
  const double feed = c.summary.contains("tool") ? number_at(c.summary["tool"], "feed", 1.0) : 1.0;
  for (double& v : t) v *= feed;
  return t;
}

bool any_nonzero(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return std::isfinite(x) && std::abs(x) > 1e-9; });
}

// A plot with its file stem, title and axis labels.
PlotSpec titled(const std::string& stem, const std::string& title, const std::string& xlabel, const std::string& ylabel) {
  PlotSpec p;
  p.stem = stem;
  p.title = title;
  p.xlabel = xlabel;
  p.ylabel = ylabel;
  return p;
}

PlotSpec force_plot(const RunContent& c) {
  PlotSpec p = titled("run_force", "Tool force (by the sheet on the tool)", "tool travel [mm]", "force [N]");
  std::vector<double> x = travel(c);
  if (tool_moved_vertically_only(c)) {  // tool-tip depth below the first touch
    const std::vector<double> z = c.force.column("tool_z");
    const double z0 = c.summary.contains("tool") ? number_at(c.summary["tool"], "radius", 0.0) + 0.5 * number_at(c.summary["model"], "thickness", 0.0)
                                                 : 0.0;
    for (std::size_t i = 0; i < x.size() && i < z.size(); ++i) x[i] = z0 - z[i];
    p.xlabel = "tool-tip depth [mm]";
  }
  const bool cone = has_polar_force(c);
  for (const char* name : cone ? std::vector<const char*>{"Fr", "Ftheta", "Fz"} : std::vector<const char*>{"Fx", "Fy", "Fz"}) {
    const std::vector<double> y = c.force.column(name);
    if (y.empty() || (std::string(name) != "Fz" && !any_nonzero(y))) continue;
    p.series.push_back({std::string(name) == "Ftheta" ? "Fθ" : name, x, y, Series::Style::line, ""});
  }
  return p;
}

// Columns of a per-contour table (contours.csv, sections.csv) against the contour's number in
// the order run; series titles by column.
PlotSpec per_contour_plot(const OutputTable& t, const std::string& stem, const std::string& title, const std::string& ylabel,
                          const std::vector<std::pair<std::string, std::string>>& columns) {
  PlotSpec p = titled(stem, title, "contour (in the order run)", ylabel);
  p.integer_x = true;
  std::vector<double> x;
  for (std::size_t i = 0; i < t.rows(); ++i) x.push_back(static_cast<double>(i + 1));
  for (const auto& [column, series] : columns) {
    const std::vector<double> y = t.column(column);
    if (!y.empty()) p.series.push_back({series, x, y, Series::Style::linespoints, ""});
  }
  return p;
}

PlotSpec contour_plot(const RunContent& c) {
  return per_contour_plot(c.contours, "run_contour_means", "Mean force over the central third of each contour", "mean force [N]",
                          {{"Fr", "Fr"}, {"Ftheta", "Fθ"}, {"Fz", "Fz"}});
}

PlotSpec section_plot(const RunContent& c, const char* column, const std::string& label, const std::string& stem) {
  PlotSpec p = titled(stem, "Section y = 0 (mid-surface): " + label, "x [mm]", label + " [mm]");
  for (const auto& [point, t] : c.sections) p.series.push_back({"at " + point, t.column("x"), t.column(column), Series::Style::line, ""});
  return p;
}

PlotSpec cone_depth_plot(const RunContent& c) {
  return per_contour_plot(c.cone_sections, "run_cone_shape", "Part centre depth and thinnest wall after each contour", "length [mm]",
                          {{"centre_depth", "centre depth"}, {"min_thickness", "thinnest wall"}});
}

// The scaled sensitivities of the tool force (sensitivities.csv: "P*dFx/d(P)" .. "P*dFz/d(P)"
// per parameter P) along the travel of force.csv's rows (the two files have a row per increment
// each): the components that carry any (above 1e-3 of the largest; an indentation's Fz alone, a
// line test's Fx and Fz). A cone's (force.csv has the tool's polar angle theta) turned into Fr,
// Ftheta, Fz as its force is.
PlotSpec sensitivity_plot(const RunContent& c) {
  PlotSpec p = titled("run_sensitivities", "Scaled sensitivities of the tool force: P dF/dP", "tool travel [mm]", "P dF/dP [N]");
  std::vector<double> x = travel(c);
  x.resize(std::min(x.size(), c.sensitivities.rows()));
  std::vector<double> theta = c.force.column("theta");
  const bool polar = !theta.empty();
  theta.resize(x.size(), 0.0);
  static const char* const kCartesian[3] = {"Fx", "Fy", "Fz"};
  static const char* const kPolar[3] = {"Fr", "Fθ", "Fz"};
  struct Column {
    std::string title;
    std::vector<double> y;
    int component;
  };
  std::vector<Column> columns;
  double largest = 0.0, by_component[3] = {0.0, 0.0, 0.0};
  for (const std::string& name : c.sensitivities.names) {
    const std::string marker = "*dFx/d(";
    const auto at = name.find(marker);
    if (at == std::string::npos) continue;
    const std::string parameter = name.substr(0, at), tail = name.substr(at + marker.size());
    std::vector<double> f[3];
    for (int k = 0; k < 3; ++k) {
      f[k] = c.sensitivities.column(parameter + "*dF" + "xyz"[k] + "/d(" + tail);
      f[k].resize(x.size(), 0.0);
    }
    if (polar)
      for (std::size_t i = 0; i < x.size(); ++i) {
        const double t = theta[i] * std::numbers::pi / 180.0, fx = f[0][i], fy = f[1][i];
        f[0][i] = std::cos(t) * fx + std::sin(t) * fy;
        f[1][i] = -std::sin(t) * fx + std::cos(t) * fy;
      }
    for (int k = 0; k < 3; ++k) {
      for (double v : f[k]) by_component[k] = std::max(by_component[k], std::abs(v));
      largest = std::max(largest, by_component[k]);
      columns.push_back({parameter + ": " + (polar ? kPolar : kCartesian)[k], std::move(f[k]), k});
    }
  }
  for (Column& col : columns)
    if (by_component[col.component] > 1e-3 * largest) p.series.push_back({col.title, x, std::move(col.y), Series::Style::line, ""});
  return p;
}

PlotSpec energy_plot(const RunContent& c) {
  PlotSpec p = titled("run_energies", "Energy account", "tool travel [mm]", "energy [N mm]");
  const std::vector<double> x = c.energies.column("travel");
  for (const char* name : {"external_work", "elastic", "plastic", "friction_dissipation", "contact_stored", "balance_error"}) {
    const std::vector<double> y = c.energies.column(name);
    if (!y.empty() && any_nonzero(y)) {
      std::string title = name;
      std::replace(title.begin(), title.end(), '_', ' ');
      p.series.push_back({title, x, y, Series::Style::line, ""});
    }
  }
  return p;
}

// An explicit run's force.csv "iterations" are the steps of each output interval.
bool explicit_run(const RunContent& c) { return c.summary.contains("explicit") && c.summary["explicit"].is_object(); }

PlotSpec iterations_plot(const RunContent& c) {
  const bool dynamic = explicit_run(c);
  PlotSpec p = titled("run_iterations", dynamic ? "Time steps per output interval" : "Newton iterations per increment", "tool travel [mm]",
                      dynamic ? "steps" : "iterations");
  p.key = false;
  p.integer_y = true;
  p.series.push_back({"iterations", travel(c), c.force.column("iterations"), Series::Style::points, ""});
  return p;
}

void read_tables(const fs::path& dir, RunContent& c, std::vector<std::string>* warnings) {
  std::string why;
  auto optional_table = [&](const char* file, OutputTable* t) {
    if (fs::exists(dir / file) && !read_output_table(dir / file, t, &why)) warnings->push_back(why);
  };
  optional_table("force.csv", &c.force);
  optional_table("energies.csv", &c.energies);
  optional_table("contours.csv", &c.contours);
  optional_table("sections.csv", &c.cone_sections);
  optional_table("sensitivities.csv", &c.sensitivities);
  std::error_code ec;
  // An axisymmetric run's sections/ holds its radial sections after each contour (sections.csv
  // lists them); the sections at named path points are the others'.
  if (has_polar_force(c) || !fs::is_directory(dir / "sections", ec)) return;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir / "sections", ec))
    if (e.path().extension() == ".csv" && e.path().stem().string().rfind("section_", 0) == 0) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    OutputTable t;
    if (read_output_table(f, &t, &why)) c.sections.emplace_back(f.stem().string().substr(8), std::move(t));
    else warnings->push_back(why);
  }
}

void render_plots(const fs::path& dir, const ReportOptions& options, RunContent& c, RunReportSummary& out) {
  if (!options.plots) return;
  const fs::path gnuplot = find_gnuplot(options.gnuplot, &out.warnings);
  if (gnuplot.empty()) return;
  PlotSession session(gnuplot, dir / "plots");
  auto add = [&](const PlotSpec& spec, const std::string& caption) {
    if (spec.series.empty()) return;
    const fs::path image = session.render(spec);
    if (!image.empty()) c.figures.emplace_back("plots/" + image.filename().string(), caption);
  };
  const bool cone = has_polar_force(c);
  if (c.force.rows() > 0) add(force_plot(c), cone ? "Tool force in polar components at the tool's angle (Fr outward, Fθ along the path)" : "Tool force");
  if (c.contours.rows() > 0) add(contour_plot(c), "Contour means (thesis §8.3: the steady state of the forming forces)");
  if (c.cone_sections.rows() > 0) add(cone_depth_plot(c), "Shape after each contour");
  if (!c.sections.empty()) {
    add(section_plot(c, "z", "z", "run_section_shape"), "Sections at the named path points: shape");
    add(section_plot(c, "thickness", "thickness", "run_section_thickness"), "Sections at the named path points: thickness");
  }
  if (c.sensitivities.rows() > 0 && c.force.rows() > 0)
    add(sensitivity_plot(c), "Sensitivities of Fz to the card's parameters (direct differentiation), each scaled by the parameter's value: "
                             "the change of Fz a 100 % change of the parameter would make, to first order (sensitivities.csv)");
  if (c.energies.rows() > 0) add(energy_plot(c), "Energy account (balance error: external work minus the stored and dissipated parts)");
  if (c.force.has("iterations"))
    add(iterations_plot(c), explicit_run(c) ? "Time steps of each output interval" : "Newton iterations of each increment");
  out.plots = session.images();
  out.warnings.insert(out.warnings.end(), session.warnings().begin(), session.warnings().end());
}

// The text of a summary value: numbers to 6 significant digits, texts and booleans as they are.
std::string value_text(const json& v) {
  if (v.is_number()) return format_significant(v.get<double>(), 6);
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

// The scene's inputs as the run recorded them in summary.json (sheet, tool, contact, solver).
void add_inputs(Document& d, const json& s) {
  Table t;
  t.id = "inputs";
  t.header = {"input", "value"};
  t.right = {false, true};
  for (const char* group : {"model", "tool", "contact", "solver"}) {
    if (!s.contains(group) || !s[group].is_object()) continue;
    for (const auto& [key, v] : s[group].items())
      if (!v.is_object() && !v.is_array()) t.rows.push_back({cell(std::string(group) + "." + key), cell(value_text(v))});
  }
  if (t.rows.empty()) return;
  d.heading(2, "Inputs", "inputs");
  d.table(t);
  d.para({{"As the run used them (summary.json): the sheet's model, the tool, the contact and the solver."}});
}

Document run_document(const RunContent& c) {
  const json& s = c.summary;
  Document d;
  d.title = "spifit run report: " + s.value("scene", std::string("?")) + " (" + s.value("kind", std::string("?")) + ")";
  const std::string status = s.value("status", "?");
  if (status == "running") {
    d.callout(CalloutKind::note, "Status: running (or killed while running)",
              {{{"The files hold the increments done so far; this report shows them."}}});
  } else if (status != "ok") {
    d.callout(CalloutKind::warning, "Status: " + status, {{{s.value("message", std::string("no message"))}}});
  }
  if (s.contains("warnings") && s["warnings"].is_array() && !s["warnings"].empty()) {
    std::vector<Inline> items;
    for (const auto& w : s["warnings"]) items.push_back({{w.get<std::string>()}});
    d.callout(CalloutKind::warning, "Warnings", items);
  }
  d.heading(2, "Summary", "summary");
  Table t;
  t.id = "summary";
  t.header = {"item", "value"};
  auto row = [&](const std::string& k, const std::string& v) { t.rows.push_back({cell(k), cell(v)}); };
  row("scene file", s.value("scene_file", std::string("n/a")));
  if (s.contains("description")) row("description", s.value("description", std::string()));
  row("material", s.value("material", std::string("n/a")));
  row("status", status);
  if (s.contains("model")) row("elements", format_significant(number_at(s["model"], "elements"), 10));
  const bool dynamic = explicit_run(c);
  if (dynamic) {
    // An explicit run (docs/design/explicit.md): output intervals and steps, not Newton increments.
    const json& e = s["explicit"];
    row("scheme", "explicit, " + e.value("contact", std::string("penalty")) + " contact");
    row("output intervals / steps / cut steps", format_significant(number_at(s, "increments"), 10) + " / " +
                                                    format_significant(number_at(e, "steps"), 10) + " / " +
                                                    format_significant(number_at(e, "cut_steps"), 10));
    row("mass scaling / time scaling", format_significant(number_at(e, "mass_scaling"), 4) + " / " + format_significant(number_at(e, "time_scaling"), 4));
    if (e.contains("time_step")) row("time step", with_unit(format_significant(number_at(e["time_step"], "start"), 4), "s"));
    row("largest kinetic over internal energy", format_percent(number_at(e, "max_kinetic_over_internal")));
  } else {
    row("increments / Newton iterations / cut-backs", format_significant(number_at(s, "increments"), 10) + " / " +
                                                          format_significant(number_at(s, "newton_iterations"), 10) + " / " +
                                                          format_significant(number_at(s, "cutbacks"), 10));
  }
  if (s.contains("travel_reached")) row("tool travel reached", with_unit(format_significant(number_at(s, "travel_reached"), 6), "mm"));
  if (s.contains("contours_completed"))
    row("contours", format_significant(number_at(s, "contours_completed"), 10) + " of " + format_significant(number_at(s, "contours_total"), 10));
  row("peak force (x, y, z)", force_text(s.value("peak_force", json())));
  if (s.contains("peak_polar_force")) row("peak force (r, θ, z)", force_text(s["peak_polar_force"]));
  row("final force (x, y, z)", force_text(s.value("final_force", json())));
  const double h = s.contains("model") ? number_at(s["model"], "thickness") : NAN;
  const double pen = number_at(s, "max_penetration");
  row("largest penetration of the tool", with_unit(format_significant(pen, 3), "mm") +
                                             (std::isfinite(h) && h > 0 ? " (" + format_percent(pen / h) + " of the thickness)" : ""));
  if (s.contains("energies") && s["energies"].is_object()) {
    const json& e = s["energies"];
    row("energy balance error", with_unit(format_significant(number_at(e, "balance_error"), 4), "N mm") + " (" +
                                    format_percent(number_at(e, "relative_balance_error")) + " of the external work)");
  }
  row("wall time", with_unit(format_significant(number_at(s, "wall_seconds"), 4), "s"));
  d.table(t);
  add_inputs(d, s);
  if (s.contains("profile_seconds") && !dynamic) {  // the Newton solver's profile
    const json& p = s["profile_seconds"];
    const double wall = number_at(s, "wall_seconds"), el = number_at(p, "elements", 0.0), as = number_at(p, "assembly", 0.0),
                 li = number_at(p, "linear_solver", 0.0);
    Table r;
    r.id = "time";
    r.header = {"where the time went", "seconds", "share"};
    r.right = {false, true, true};
    auto line = [&](const std::string& k, double v) { r.rows.push_back({cell(k), cell(format_fixed(v, 2)), cell(format_percent(v / wall))}); };
    line("element evaluation (parallel)", el);
    line("scatter into the tangent", as);
    line("linear solver (factorisation and solves)", li);
    line("the rest (contact search, outputs, predictor)", std::max(0.0, wall - el - as - li));
    d.heading(2, "Run time", "time");
    d.table(r);
  }
  if (!c.figures.empty()) d.heading(2, "Plots", "plots");
  for (const auto& [src, caption] : c.figures) d.figure(src, caption);
  d.para({{"Files: "}, {"force.csv", false, true}, {" (tool force per increment), "}, {"energies.csv", false, true}, {", "},
          {"summary.json", false, true}, {" (every number above), "}, {"vtu/", false, true},
          {" (ParaView). Re-render with "}, {"spifit report DIR", false, true}, {"."}});
  return d;
}

}  // namespace

bool is_fe_run_directory(const fs::path& dir) {
  const auto s = read_summary(dir);
  return s && is_fe_kind(*s);
}

RunReportSummary render_run_report(const fs::path& dir, const ReportOptions& options) {
  const auto summary = read_summary(dir);
  if (!summary || !is_fe_kind(*summary))
    throw io::InputError((dir / "summary.json").string(), "", "",
                         "no summary.json of an FE run (" + fe_kind_names() + ") here: not an output directory of `spifit run`");
  RunReportSummary out;
  RunContent c;
  c.summary = *summary;
  read_tables(dir, c, &out.warnings);
  render_plots(dir, options, c, out);
  const ReportFiles files = write_report_files(dir, run_document(c));
  out.markdown = files.markdown;
  out.html = files.html;
  return out;
}

}  // namespace spifit::reports
