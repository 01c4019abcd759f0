// Reading a sweep file (schema: docs/reference/file-formats.md, "Sweep file").
#include "inverse/sweeps/sweep.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "forward/scenes/sensitivity_refusal.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace spifit::inverse {
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

std::string names_of(const std::vector<scene::Observable>& obs) {
  std::string s;
  for (const auto& o : obs) s += (s.empty() ? "" : ", ") + o.name;
  return s;
}

// The kind's own numeric inputs and the card's parameters, for error messages.
std::string input_names(const scene::SceneKind& k, bool with_card) {
  std::string s;
  for (const auto& i : k.inputs)
    if (i.type != io::InputType::text && i.variable) s += (s.empty() ? "" : ", ") + i.name;
  if (with_card) s += s.empty() ? "a material parameter (hill.N, swift.K, ...)" : "; or a material parameter (hill.N, swift.K, ...)";
  return s;
}

void read_metrics(const io::TomlTable& st, SweepSpec& s) {
  const std::string known = names_of(s.kind->observables);
  if (!st.has("metrics")) st.fail("metrics", "required: a list of metric names (" + known + ")");
  s.metrics = st.string_list("metrics");
  if (s.metrics.empty()) st.fail("metrics", "must list at least one metric name");
  for (const auto& m : s.metrics) {
    const scene::Observable* o = s.kind->find_observable(m);
    if (!o) st.fail("metrics", "unknown metric \"" + m + "\" for scene kind " + s.kind->name + " (known: " + known + ")");
    if (o->needs == scene::Observable::Needs::window && !s.options.window)
      st.fail("metrics", "metric \"" + m + "\" needs window = [from_mm, to_mm] in [sweep] (mm of tool travel)");
    if (o->needs == scene::Observable::Needs::contours && !s.options.contours)
      st.fail("metrics", "metric \"" + m + "\" needs contours = [from, to] in [sweep] (1-based contour numbers)");
  }
}

// Whether any observable of the kind needs the option, and the kinds that have one that does.
bool kind_needs(const scene::SceneKind& k, scene::Observable::Needs needs) {
  for (const auto& o : k.observables)
    if (o.needs == needs) return true;
  return false;
}
std::string kinds_needing(scene::Observable::Needs needs) {
  std::string s;
  for (const auto& k : scene::scene_kinds())
    if (kind_needs(k, needs)) s += (s.empty() ? "" : ", ") + k.name;
  return s;
}

void read_options(const io::TomlTable& st, SweepSpec& s) {
  using Needs = scene::Observable::Needs;
  if (st.has("window")) {
    if (!kind_needs(*s.kind, Needs::window))
      st.fail("window", "only for scene kinds with metrics over a travel window (" + kinds_needing(Needs::window) + "), not " + s.kind->name);
    const auto w = st.number_list("window");
    if (w.size() != 2) st.fail("window", "expected [from_mm, to_mm] (tool travel)");
    if (!(w[0] >= 0.0 && w[1] > w[0])) st.fail("window", "expected 0 <= from_mm < to_mm (tool travel)");
    s.options.window = std::array<double, 2>{w[0], w[1]};
  }
  if (st.has("contours")) {
    if (!kind_needs(*s.kind, Needs::contours))
      st.fail("contours", "only for scene kinds with metrics over contours (" + kinds_needing(Needs::contours) + "), not " + s.kind->name);
    const auto c = st.number_list("contours");
    if (c.size() != 2 || c[0] != std::floor(c[0]) || c[1] != std::floor(c[1]) || !(c[0] >= 1 && c[1] >= c[0]))
      st.fail("contours", "expected [from, to]: whole contour numbers with 1 <= from <= to");
    s.options.contours = std::make_pair(static_cast<int>(c[0]), static_cast<int>(c[1]));
  }
}

// One [inputs."NAME"] table: a named input of the scene, its values checked one by one.
SweepInput read_input(const io::TomlTable& inputs, const std::string& name, const SweepSpec& s) {
  const io::InputInfo* own = nullptr;
  for (const auto& i : s.kind->inputs)
    if (i.name == name) own = &i;
  const material::MaterialInput* material_input = material::find_material_input(name);
  const bool card = material_input && s.scene->card();
  if (!(own && own->variable && own->type != io::InputType::text) && !card)
    inputs.fail(name, "not an input a sweep can vary for scene kind " + s.kind->name + " (inputs: " + input_names(*s.kind, s.scene->card()) + ")");
  if (card && !own)
    if (const std::string why = material::why_not_held(s.scene->card()->params, *material_input); !why.empty()) inputs.fail(name, why);
  const auto t = inputs.table(name);
  if (!t) inputs.fail(name, "expected a table: values = [...] or from, to, steps, log");
  SweepInput in{name, read_input_values(*t), own && own->type == io::InputType::integer};
  std::string key = t->key_path(t->has("values") ? "values" : "");
  if (key.back() == '.') key.pop_back();  // generated values: named by the input's table
  for (double& v : in.values) {
    // Integer inputs: values within rounding of an integer (log spacing) become that integer.
    if (in.integer && std::abs(v - std::round(v)) <= 1e-9 * std::max(1.0, std::abs(v))) v = std::round(v);
    const std::string why = s.scene->clone()->set_input(name, v);
    if (!why.empty()) throw io::InputError(t->file(), key, io::format_number(v), why);
  }
  return in;
}

// Every grid point is a valid scene (combinations of inputs included).
void check_grid(const SweepSpec& s) {
  for (const auto& g : sweep_grid(s)) {
    auto sc = s.scene->clone();
    for (std::size_t k = 0; k < s.inputs.size(); ++k) {
      const std::string why = sc->set_input(s.inputs[k].name, g[k]);
      if (!why.empty())
        throw io::InputError(s.file, "inputs." + s.inputs[k].name, io::format_number(g[k]), why + " (at a grid point with the other inputs)");
    }
  }
}

// [sweep] exact_sensitivities: the scene must run with sensitivities with respect to every input
// (sensitivity_refusal.hpp) and a metric must have derivatives.
void read_exact(const io::TomlTable& st, SweepSpec& s) {
  s.exact = st.boolean("exact_sensitivities", false);
  if (!s.exact) return;
  std::vector<std::string> names;
  for (const auto& in : s.inputs) names.push_back(in.name);
  if (const auto r = scene::sensitivity_refusal(*s.scene, names))
    st.fail("exact_sensitivities", (r->key == "--sensitivities" ? "" : r->key + " = " + r->value + ": ") + r->why);
  std::string without;
  for (std::size_t m = 0; m < s.metrics.size(); ++m) {
    if (s.kind->find_observable(s.metrics[m])->derivatives) s.exact_metrics.push_back(static_cast<int>(m));
    else without += (without.empty() ? "" : ", ") + s.metrics[m];
  }
  if (s.exact_metrics.empty()) st.fail("exact_sensitivities", "none of the metrics has derivatives (" + without + ")");
}

}  // namespace

SweepSpec read_sweep_file(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"sweep", "inputs"});
  const auto st = root.table("sweep");
  if (!st) root.fail("sweep", "required table [sweep] is missing");
  st->allow_only({"name", "scene", "card", "metrics", "sensitivities", "relative_step", "window", "contours", "exact_sensitivities"});
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
  std::unique_ptr<scene::Scene> sc = scene::read_scene(scene_path);
  s.kind = scene::find_scene_kind(sc->kind());
  if (st->has("card")) {
    if (!sc->card()) st->fail("card", "scene kind " + sc->kind() + " has no material card");
    const std::string c = resolve(st->string("card"));
    if (!std::filesystem::exists(c)) st->fail("card", "card not found at " + c);
    *sc->card() = material::load_material_card(c);
  }
  s.scene = std::move(sc);
  read_options(*st, s);
  read_metrics(*st, s);
  // FE runs take seconds to hours each: sensitivities (2 runs per input) on request.
  s.sensitivities = st->boolean("sensitivities", s.kind->parallel_sweeps);
  s.relative_step = st->number("relative_step", 0.01);
  if (!(s.relative_step > 0 && s.relative_step < 0.5)) st->fail("relative_step", "must lie in (0, 0.5)");
  const auto it = root.table("inputs");
  if (!it) root.fail("inputs", "required table [inputs] with at least one input");
  for (const auto& name : it->keys()) s.inputs.push_back(read_input(*it, name, s));
  if (s.inputs.empty()) root.fail("inputs", "at least one input");
  check_grid(s);
  read_exact(*st, s);
  return s;
}

std::vector<std::string> sweep_input_files(const SweepSpec& s) {
  std::vector<std::string> files{s.file};
  for (const auto& f : s.scene->input_files()) files.push_back(f);
  if (s.scene->card() && !s.scene->card()->file.empty()) files.push_back(s.scene->card()->file);
  return files;
}

}  // namespace spifit::inverse
