#include "inverse/sweep.hpp"

#include "inverse/forming_sweep.hpp"

#include "forward/io/csv_writer.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace spifit::inverse {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<std::string>& metric_list() {
  static const std::vector<std::string> m{"r_value",      "yield_stress", "initial_yield_stress", "reverse_yield_stress",
                                          "final_stress", "max_abs_stress", "final_eqps",         "final_thickness_strain"};
  return m;
}

double metric(const scene::MaterialPointResult<double>& r, const std::string& name) {
  if (!r.ok || r.curve.empty()) return kNaN;
  if (name == "r_value") return r.r_value ? *r.r_value : kNaN;
  if (name == "yield_stress") return r.offset_yield_stress ? *r.offset_yield_stress : kNaN;
  if (name == "initial_yield_stress") return r.yield_events.empty() ? kNaN : r.yield_events.front().stress;
  if (name == "reverse_yield_stress") {
    for (const auto& e : r.yield_events) if (e.segment == 1) return e.stress;
    return kNaN;
  }
  if (name == "final_stress") return r.curve.back().stress;
  if (name == "max_abs_stress") {
    double m = 0.0;
    for (const auto& p : r.curve) m = std::max(m, std::abs(p.stress));
    return m;
  }
  if (name == "final_eqps") return r.curve.back().eqps;
  if (name == "final_thickness_strain") return r.curve.back().thickness_strain;
  return kNaN;
}

// Runs the scene with the named inputs set to `values` on top of the base card.
SweepPoint run_point(const SweepSpec& s, const std::vector<double>& values) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepPoint p;
  p.inputs = values;
  std::vector<ParameterSpec> specs;
  for (std::size_t i = 0; i < s.inputs.size(); ++i) specs.push_back({s.inputs[i].name, values[i], values[i], values[i], true, false});
  const ParameterSet ps(s.scene.card, specs, false);
  const auto card = ps.card_for({});
  try {
    material::validate_material_card(card);
    const auto r = scene::run_material_point(card.params, s.scene.setup);
    p.ok = r.ok;
    p.message = r.message;
    for (const auto& m : s.metrics) p.metrics.push_back(metric(r, m));
  } catch (const std::exception& e) {
    p.ok = false;
    p.message = e.what();
    p.metrics.assign(s.metrics.size(), kNaN);
  }
  p.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace

const char* sweep_metric_names() {
  return "r_value, yield_stress, initial_yield_stress, reverse_yield_stress, final_stress, max_abs_stress, final_eqps, final_thickness_strain";
}
bool is_sweep_metric(const std::string& n) {
  for (const auto& m : metric_list()) if (m == n) return true;
  return false;
}

namespace {

// Log spacing rounds in exp/log (up to a few 1e-15 relative): 12 significant digits keep
// decades exact (100, not 100.00000000000004) in the grid, sweep.csv and the progress lines.
double round_to_12_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return std::strtod(buf, nullptr);
}

// values = [...] or from, to, steps (>= 2), log (geometric spacing).
std::vector<double> read_input_values(const io::TomlTable& t) {
  t.allow_only({"values", "from", "to", "steps", "log"});
  std::vector<double> values;
  if (t.has("values")) {
    values = t.number_list("values");
    if (values.empty()) t.fail("values", "must hold at least one value");
    return values;
  }
  const double a = t.number("from"), b = t.number("to");
  const int n = t.integer("steps", 5);
  if (n < 2) t.fail("steps", "must be >= 2");
  const bool lg = t.boolean("log", false);
  if (lg && !(a > 0 && b > 0)) t.fail("from", "log spacing needs from, to > 0");
  for (int i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / (n - 1);
    double v = lg ? round_to_12_digits(std::exp(std::log(a) + f * (std::log(b) - std::log(a)))) : a + f * (b - a);
    if (i == 0) v = a;  // exact end points
    if (i == n - 1) v = b;
    values.push_back(v);
  }
  return values;
}

// Integer scene keys: values within rounding of an integer (log spacing) become that integer.
void snap_integers(const std::string& name, std::vector<double>& values) {
  if (!is_integer_forming_key(name)) return;
  for (double& v : values) {
    const double r = std::round(v);
    if (std::abs(v - r) <= 1e-9 * std::max(1.0, std::abs(v))) v = r;
  }
}

void read_metrics(const io::TomlTable& st, SweepSpec& s) {
  const bool forming = s.forming.has_value();
  const char* known = forming ? forming_metric_names() : sweep_metric_names();
  if (!st.has("metrics")) st.fail("metrics", std::string("required: a list of metric names (") + known + ")");
  s.metrics = st.string_list("metrics");
  if (s.metrics.empty()) st.fail("metrics", "must list at least one metric name");
  for (const auto& m : s.metrics) {
    if (forming && is_sweep_metric(m))
      st.fail("metrics", "\"" + m + "\" is a material-point metric; this scene is a forming scene (metrics: " + known + ")");
    if (!forming && is_forming_metric(m))
      st.fail("metrics", "\"" + m + "\" is a forming-scene metric; this scene is a material-point scene (metrics: " + known + ")");
    if (!(forming ? is_forming_metric(m) : is_sweep_metric(m))) st.fail("metrics", "unknown metric \"" + m + "\" (known: " + known + ")");
  }
}

void read_inputs(const io::TomlTable& root, SweepSpec& s) {
  const auto it = root.table("inputs");
  if (!it) root.fail("inputs", "required table [inputs] with at least one parameter");
  for (const auto& name : it->keys()) {
    if (s.forming) {
      if (!is_known_parameter(name) && !is_forming_scene_key(name))
        it->fail(name, std::string("unknown input (forming scene keys: ") + forming_scene_key_names() + "; or a material parameter)");
    } else if (is_forming_scene_key(name)) {
      it->fail(name, "a forming-scene key; this scene is a material-point scene (inputs: material parameters)");
    } else if (!is_known_parameter(name)) {
      it->fail(name, "unknown parameter");
    }
    const auto t = it->table(name);
    SweepInput in{name, read_input_values(*t)};
    if (s.forming) {
      snap_integers(name, in.values);
      check_forming_input(*t, s.forming->scene, name, in.values);
    }
    s.inputs.push_back(in);
  }
  if (s.inputs.empty()) root.fail("inputs", "at least one input");
}

// Every grid point of a forming sweep is a valid scene (combinations of inputs included).
void check_forming_grid(const SweepSpec& s) {
  for (const auto& g : sweep_grid(s)) {
    scene::FormingScene sc = s.forming->scene;
    for (std::size_t k = 0; k < s.inputs.size(); ++k) set_forming_input(sc, s.inputs[k].name, g[k]);
    for (std::size_t k = 0; k < s.inputs.size(); ++k) {
      const std::string err = forming_input_error(sc, s.inputs[k].name, g[k]);
      if (!err.empty()) throw io::InputError(s.file, "inputs." + s.inputs[k].name, io::format_number(g[k]), err + " (at a grid point with the other inputs)");
    }
  }
}

}  // namespace

SweepSpec read_sweep_file(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"sweep", "inputs"});
  const auto st = root.table("sweep");
  if (!st) root.fail("sweep", "required table [sweep] is missing");
  st->allow_only({"name", "scene", "card", "metrics", "sensitivities", "relative_step", "window"});
  SweepSpec s;
  s.file = path;
  s.name = st->string("name", std::filesystem::path(path).stem().string());
  auto resolve = [&](const std::string& p) {
    std::filesystem::path q(p);
    if (q.is_relative()) q = std::filesystem::path(path).parent_path() / q;
    return q.lexically_normal().string();
  };
  const std::string scene_path = resolve(st->string("scene"));
  if (!std::filesystem::exists(scene_path)) st->fail("scene", "scene file not found at " + scene_path);
  if (scene::is_forming_kind(scene::scene_kind(scene_path))) {
    s.forming = FormingSweepSetup{scene::read_forming_scene(scene_path), std::nullopt};
  } else {
    if (st->has("window")) st->fail("window", "only for forming scenes (indent, indent_line, line)");
    s.scene = scene::read_scene_file(scene_path);
  }
  if (st->has("card")) {
    const std::string c = resolve(st->string("card"));
    if (!std::filesystem::exists(c)) st->fail("card", "card not found at " + c);
    (s.forming ? s.forming->scene.card : s.scene.card) = material::load_material_card(c);
  }
  read_metrics(*st, s);
  if (s.forming) read_forming_window(*st, s.metrics, *s.forming);
  // Forming runs take seconds to minutes each: sensitivities (2 runs per input) on request.
  s.sensitivities = st->boolean("sensitivities", !s.forming);
  s.relative_step = st->number("relative_step", 0.01);
  if (!(s.relative_step > 0 && s.relative_step < 0.5)) st->fail("relative_step", "must lie in (0, 0.5)");
  read_inputs(root, s);
  if (s.forming) check_forming_grid(s);
  return s;
}

std::vector<std::string> sweep_input_files(const SweepSpec& s) {
  if (!s.forming) return {s.file, s.scene.file, s.scene.card.file};
  std::vector<std::string> files{s.file, s.forming->scene.file, s.forming->scene.card.file};
  if (!s.forming->scene.gcode.empty()) files.push_back(s.forming->scene.gcode);
  return files;
}

std::vector<std::vector<double>> sweep_grid(const SweepSpec& s) {
  std::vector<std::vector<double>> grid{{}};
  for (const auto& in : s.inputs) {
    std::vector<std::vector<double>> next;
    for (const auto& g : grid) {
      for (double v : in.values) {
        auto h = g;
        h.push_back(v);
        next.push_back(h);
      }
    }
    grid = next;
  }
  return grid;
}

double log_sensitivity(double base_input, double up, double down, double h) {
  if (base_input == 0.0 || !(up / down > 0.0)) return kNaN;
  return std::log(up / down) / std::log((1.0 + h) / (1.0 - h));
}

SweepResult run_sweep(const SweepSpec& s, const SweepRunOptions& o) {
  if (s.forming) {
    if (!o.out) throw std::invalid_argument("run_sweep: a forming sweep needs an output directory (DIR/points/NNN)");
    return run_forming_sweep(s, *o.out, o.progress);
  }
  return run_sweep(s, o.threads);
}

SweepResult run_sweep(const SweepSpec& s, int threads) {
  if (s.forming) throw std::invalid_argument("run_sweep: a forming sweep needs SweepRunOptions with an output directory");
  const auto t0 = std::chrono::steady_clock::now();
  const auto grid = sweep_grid(s);
  SweepResult r;
  r.points.resize(grid.size());
  const int n = static_cast<int>(grid.size());
#pragma omp parallel for schedule(dynamic) num_threads(std::max(1, threads))
  for (int i = 0; i < n; ++i) r.points[i] = run_point(s, grid[i]);

  if (s.sensitivities) {
    std::vector<double> base;
    for (const auto& in : s.inputs) base.push_back(parameter_value(s.scene.card, in.name));
    const SweepPoint b = run_point(s, base);
    for (std::size_t k = 0; k < s.inputs.size(); ++k) {
      auto up = base, dn = base;
      up[k] *= 1.0 + s.relative_step;
      dn[k] *= 1.0 - s.relative_step;
      const SweepPoint pu = run_point(s, up), pd = run_point(s, dn);
      for (std::size_t m = 0; m < s.metrics.size(); ++m) {
        r.sensitivities.push_back(
            {s.inputs[k].name, s.metrics[m], base[k], b.metrics[m], log_sensitivity(base[k], pu.metrics[m], pd.metrics[m], s.relative_step)});
      }
    }
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

std::string sweep_csv(const SweepSpec& s, const SweepResult& r) {
  std::vector<std::string> cols;
  for (const auto& in : s.inputs) cols.push_back(in.name);
  for (const auto& m : s.metrics) cols.push_back(m);
  cols.push_back("wall_seconds");
  cols.push_back("ok");
  io::CsvTable t(cols);
  for (const auto& p : r.points) {
    std::vector<double> row = p.inputs;
    row.insert(row.end(), p.metrics.begin(), p.metrics.end());
    row.push_back(p.wall_seconds);
    row.push_back(p.ok ? 1.0 : 0.0);
    t.add_row(row);
  }
  return t.str();
}

std::string sensitivities_csv(const SweepResult& r) {
  std::string out = "input,metric,base_input,base_metric,dln_metric_dln_input\n";
  char buf[256];
  for (const auto& s : r.sensitivities) {
    std::snprintf(buf, sizeof buf, "%s,%s,%.17g,%.17g,%.17g\n", s.input.c_str(), s.metric.c_str(), s.base_input, s.base_metric, s.value);
    out += buf;
  }
  return out;
}

}  // namespace spifit::inverse
