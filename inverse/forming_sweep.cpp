#include "inverse/forming_sweep.hpp"

#include "forward/io/input_error.hpp"
#include "inverse/measurement.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>

namespace spifit::inverse {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<std::string>& metric_list() {
  static const std::vector<std::string> m{"peak_fx", "peak_fz", "final_fx", "final_fz", "max_penetration", "newton_iterations",
                                          "increments", "mean_fx", "mean_fy", "mean_fz", "ripple_fz"};
  return m;
}

const std::vector<std::string>& key_list() {
  static const std::vector<std::string> k{"contact.penalty", "contact.friction", "contact.points", "contact.tangential_penalty",
                                          "tool.radius", "tool.spin", "solver.travel_per_increment", "sheet.elements", "sheet.thickness_points",
                                          "sheet.thickness"};
  return k;
}

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// A material parameter set on the scene's card (validated by the caller).
material::MaterialCard card_with(const material::MaterialCard& base, const std::string& name, double value) {
  const ParameterSet ps(base, {{name, value, value, value, true, false}}, false);
  return ps.card_for({});
}

std::string positive_error(double v) { return v > 0.0 && std::isfinite(v) ? std::string() : std::string("must be > 0"); }

// The scene reader's checks of the sheet keys.
std::string sheet_error(const scene::FormingScene& s, const std::string& name) {
  if (name == "sheet.thickness") return positive_error(s.thickness);
  if (name == "sheet.elements") {
    if (s.elements < 2 || s.elements > 2000) return "must be an integer in [2, 2000]";
    if (s.half && s.elements % 2 != 0) return "a half model needs an even number of elements across";
  }
  if (name == "sheet.thickness_points" && (s.thickness_points < 1 || s.thickness_points > 11))
    return "unsupported number of thickness points (1 to 11)";
  return {};
}

// Travel window rows of force.csv: sums, extremes and count of the forces.
struct WindowStats {
  double sum[3] = {0.0, 0.0, 0.0};
  double min_fz = std::numeric_limits<double>::infinity(), max_fz = -std::numeric_limits<double>::infinity();
  std::size_t rows = 0;
};

// No force.csv (or no rows in it): an empty window.
WindowStats window_stats(const std::string& force_csv, double feed, const std::array<double, 2>& window) {
  WindowStats w;
  if (!std::filesystem::is_regular_file(force_csv)) return w;
  const MeasurementTable t = read_measurement_csv(force_csv);
  const auto& time = t.column("time");
  const std::vector<double>* f[3] = {&t.column("Fx"), &t.column("Fy"), &t.column("Fz")};
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double travel = time[i] * feed;
    if (travel < window[0] || travel > window[1]) continue;
    for (int k = 0; k < 3; ++k) w.sum[k] += (*f[k])[i];
    w.min_fz = std::min(w.min_fz, (*f[2])[i]);
    w.max_fz = std::max(w.max_fz, (*f[2])[i]);
    ++w.rows;
  }
  return w;
}

double window_metric(const WindowStats& w, const std::string& name) {
  if (w.rows == 0) return kNaN;
  const double n = static_cast<double>(w.rows);
  if (name == "mean_fx") return w.sum[0] / n;
  if (name == "mean_fy") return w.sum[1] / n;
  if (name == "mean_fz") return w.sum[2] / n;
  if (name == "ripple_fz") return (w.max_fz - w.min_fz) / (w.sum[2] / n);
  return kNaN;
}

double summary_number(const nlohmann::json& s, const char* key, int component = -1) {
  if (!s.contains(key)) return kNaN;
  const auto& v = component < 0 ? s.at(key) : s.at(key).at(static_cast<std::size_t>(component));
  return v.is_number() ? v.get<double>() : kNaN;
}

std::string point_label(const SweepSpec& s, const std::vector<double>& values) {
  std::string out;
  char buf[64];
  for (std::size_t k = 0; k < s.inputs.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%s%s=%.6g", k ? " " : "", s.inputs[k].name.c_str(), values[k]);
    out += buf;
  }
  return out;
}

// One run of the scene with the inputs at `values`, its outputs in DIR/sub/.
SweepPoint run_point(const SweepSpec& s, const std::vector<double>& values, const io::OutputDirectory& out, const std::string& sub) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepPoint p;
  p.inputs = values;
  try {
    scene::FormingScene sc = s.forming->scene;
    for (std::size_t k = 0; k < s.inputs.size(); ++k) set_forming_input(sc, s.inputs[k].name, values[k]);
    const auto dir = io::OutputDirectory::prepare((out.path() / sub).string(), false);
    const auto rep = scene::run_forming_scene(sc, dir, false);
    p.ok = rep.ok && rep.summary.value("status", std::string()) == "ok";
    p.message = rep.summary.value("message", std::string());
    p.metrics = forming_metrics(rep.summary, (dir.path() / "force.csv").string(), *s.forming, s.metrics);
  } catch (const std::exception& e) {
    p.ok = false;
    p.message = e.what();
    p.metrics.assign(s.metrics.size(), kNaN);
  }
  p.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

void report(bool progress, const std::string& what, const SweepSpec& s, const SweepPoint& p) {
  if (!progress) return;
  std::fprintf(stderr, "%s: %s -> %s in %.1f s%s%s\n", what.c_str(), point_label(s, p.inputs).c_str(), p.ok ? "ok" : "failed",
               p.wall_seconds, p.ok ? "" : ": ", p.ok ? "" : p.message.c_str());
}

// DIR/points/NNN: zero-padded to at least 3 digits, as many as the largest index needs.
std::string point_dir(std::size_t i, std::size_t n) {
  const int width = std::max(3, static_cast<int>(std::to_string(n > 0 ? n - 1 : 0).size()));
  char buf[32];
  std::snprintf(buf, sizeof buf, "points/%0*zu", width, i);
  return buf;
}

std::vector<Sensitivity> forming_sensitivities(const SweepSpec& s, const io::OutputDirectory& out, bool progress) {
  std::vector<double> base;
  bool any = false;
  for (const auto& in : s.inputs) {
    base.push_back(forming_input_value(s.forming->scene, in.name));
    any = any || (!is_integer_forming_key(in.name) && base.back() != 0.0);
  }
  std::vector<Sensitivity> r;
  SweepPoint b;
  b.metrics.assign(s.metrics.size(), kNaN);
  if (any) {
    b = run_point(s, base, out, "sensitivities/base");
    report(progress, "sensitivity base", s, b);
  }
  for (std::size_t k = 0; k < s.inputs.size(); ++k) {
    // Integer inputs have no relative step; a zero base has no logarithm: NaN, no runs.
    const bool skip = is_integer_forming_key(s.inputs[k].name) || base[k] == 0.0;
    SweepPoint pu, pd;
    if (!skip) {
      auto up = base, dn = base;
      up[k] *= 1.0 + s.relative_step;
      dn[k] *= 1.0 - s.relative_step;
      pu = run_point(s, up, out, "sensitivities/" + s.inputs[k].name + "_up");
      report(progress, "sensitivity " + s.inputs[k].name + " up", s, pu);
      pd = run_point(s, dn, out, "sensitivities/" + s.inputs[k].name + "_down");
      report(progress, "sensitivity " + s.inputs[k].name + " down", s, pd);
    }
    for (std::size_t m = 0; m < s.metrics.size(); ++m) {
      Sensitivity sv{s.inputs[k].name, s.metrics[m], base[k], b.metrics[m], kNaN};
      if (!skip) sv.value = log_sensitivity(base[k], pu.metrics[m], pd.metrics[m], s.relative_step);
      r.push_back(sv);
    }
  }
  return r;
}

}  // namespace

const char* forming_metric_names() {
  return "peak_fx, peak_fz, final_fx, final_fz, max_penetration, newton_iterations, increments, mean_fx, mean_fy, mean_fz, ripple_fz";
}
bool is_forming_metric(const std::string& name) { return contains(metric_list(), name); }
bool is_window_metric(const std::string& name) {
  return name == "mean_fx" || name == "mean_fy" || name == "mean_fz" || name == "ripple_fz";
}

const char* forming_scene_key_names() {
  return "contact.penalty, contact.friction, contact.points, contact.tangential_penalty, tool.radius, tool.spin, "
         "solver.travel_per_increment, sheet.elements, sheet.thickness_points, sheet.thickness";
}
bool is_forming_scene_key(const std::string& name) { return contains(key_list(), name); }
bool is_integer_forming_key(const std::string& name) {
  return name == "contact.points" || name == "sheet.elements" || name == "sheet.thickness_points";
}

double forming_input_value(const scene::FormingScene& s, const std::string& name) {
  if (name == "contact.penalty") return s.contact.penalty;
  if (name == "contact.friction") return s.contact.friction;
  if (name == "contact.points") return s.contact.points;
  if (name == "contact.tangential_penalty") return s.contact.tangential_penalty;
  if (name == "tool.radius") return s.radius;
  if (name == "tool.spin") return s.spin;
  if (name == "solver.travel_per_increment") return s.travel_per_increment;
  if (name == "sheet.elements") return s.elements;
  if (name == "sheet.thickness_points") return s.thickness_points;
  if (name == "sheet.thickness") return s.thickness;
  return parameter_value(s.card, name);
}

void set_forming_input(scene::FormingScene& s, const std::string& name, double v) {
  const int i = static_cast<int>(std::lround(v));
  if (name == "contact.penalty") s.contact.penalty = v;
  else if (name == "contact.friction") s.contact.friction = v;
  else if (name == "contact.points") s.contact.points = i;
  else if (name == "contact.tangential_penalty") s.contact.tangential_penalty = v;
  else if (name == "tool.radius") s.radius = v;
  else if (name == "tool.spin") s.spin = v;
  else if (name == "solver.travel_per_increment") s.travel_per_increment = v;
  else if (name == "sheet.elements") s.elements = i;
  else if (name == "sheet.thickness_points") s.thickness_points = i;
  else if (name == "sheet.thickness") s.thickness = v;
  else s.card = card_with(s.card, name, v);
}

std::string forming_input_error(const scene::FormingScene& base, const std::string& name, double v) {
  if (!std::isfinite(v)) return "must be finite";
  if (is_integer_forming_key(name) && (v != std::floor(v) || std::abs(v) > 1e9)) return name + " takes integer values";
  scene::FormingScene s = base;
  if (is_forming_scene_key(name)) {
    set_forming_input(s, name, v);
    if (name.rfind("contact.", 0) == 0) return s.contact.validate();
    if (name == "tool.radius") return positive_error(s.radius);
    if (name == "tool.spin") return std::abs(v) <= 1e5 ? std::string() : std::string("must be a rotation speed in rev/min with |spin| <= 1e5");
    if (name == "solver.travel_per_increment") return positive_error(s.travel_per_increment);
    return sheet_error(s, name);
  }
  try {
    material::validate_material_card(card_with(base.card, name, v));
  } catch (const io::InputError& e) {
    return "invalid card " + base.card.name + ": " + e.key() + (e.value().empty() ? "" : " = " + e.value()) + ": " + e.message();
  }
  return {};
}

void check_forming_input(const io::TomlTable& t, const scene::FormingScene& base, const std::string& name,
                         const std::vector<double>& values) {
  std::string key = t.key_path(t.has("values") ? "values" : "");
  if (key.back() == '.') key.pop_back();  // generated values: named by the input's table
  for (double v : values) {
    const std::string err = forming_input_error(base, name, v);
    if (!err.empty()) throw io::InputError(t.file(), key, io::format_number(v), err);
  }
}

void read_forming_window(const io::TomlTable& st, const std::vector<std::string>& metrics, FormingSweepSetup& setup) {
  if (st.has("window")) {
    const auto w = st.number_list("window");
    if (w.size() != 2) st.fail("window", "expected [from_mm, to_mm] (tool travel)");
    if (!(w[0] >= 0.0 && w[1] > w[0])) st.fail("window", "expected 0 <= from_mm < to_mm (tool travel)");
    setup.window = std::array<double, 2>{w[0], w[1]};
  }
  for (const auto& m : metrics) {
    if (is_window_metric(m) && !setup.window)
      st.fail("metrics", "metric \"" + m + "\" needs window = [from_mm, to_mm] in [sweep] (mm of tool travel)");
  }
}

std::vector<double> forming_metrics(const nlohmann::json& summary, const std::string& force_csv, const FormingSweepSetup& setup,
                                    const std::vector<std::string>& metrics) {
  // A failed run keeps its counts; its forces do not describe the whole path.
  const bool ok = summary.value("status", std::string()) == "ok";
  std::optional<WindowStats> w;
  std::vector<double> out;
  for (const auto& m : metrics) {
    double v = kNaN;
    if (m == "newton_iterations") v = summary_number(summary, "newton_iterations");
    else if (m == "increments") v = summary_number(summary, "increments");
    else if (!ok) v = kNaN;
    else if (m == "peak_fx") v = summary_number(summary, "peak_force", 0);
    else if (m == "peak_fz") v = summary_number(summary, "peak_force", 2);
    else if (m == "final_fx") v = summary_number(summary, "final_force", 0);
    else if (m == "final_fz") v = summary_number(summary, "final_force", 2);
    else if (m == "max_penetration") v = summary_number(summary, "max_penetration");
    else if (is_window_metric(m) && setup.window) {
      if (!w) w = window_stats(force_csv, setup.scene.feed, *setup.window);
      v = window_metric(*w, m);
    }
    out.push_back(v);
  }
  return out;
}

SweepResult run_forming_sweep(const SweepSpec& s, const io::OutputDirectory& out, bool progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto grid = sweep_grid(s);
  SweepResult r;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    r.points.push_back(run_point(s, grid[i], out, point_dir(i, grid.size())));
    report(progress, "point " + std::to_string(i + 1) + "/" + std::to_string(grid.size()), s, r.points.back());
  }
  if (s.sensitivities) r.sensitivities = forming_sensitivities(s, out, progress);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace spifit::inverse
