#include "inverse/experiments/material_point_experiment_file.hpp"

#include "forward/scenes/material_point/curve_columns.hpp"
#include "forward/scenes/material_point/material_point_inputs.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/experiments/measurement.hpp"

#include <algorithm>
#include <cmath>

namespace spifit::inverse {
namespace {

using io::format_number;
using io::InputError;

// Range of the simulated abscissa of a scene: [0, end] and whether it increases.
std::pair<double, double> abscissa_range(const scene::MaterialPointSetup& s, const std::string& x, bool* monotone) {
  double prev = 0.0, total = 0.0, lo = 0.0, hi = 0.0;
  bool increasing = true;
  for (double t : s.strain_path) {
    total += std::abs(t - prev);
    if (t < prev) increasing = false;
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    prev = t;
  }
  if (x == "cumulative_strain") { *monotone = true; return {0.0, total}; }
  if (x == "increment") { *monotone = true; return {0.0, double(s.increments)}; }
  *monotone = increasing;
  return {lo, hi};
}

// The observable of a scalar or a table of scalars, checked against the scene.
std::string scalar_observable_of(const io::TomlTable& e, const scene::MaterialPointScene& sc) {
  const std::string obs = e.string("observable");
  if (!is_scalar_observable(obs)) e.fail("observable", std::string("unknown observable (known: ") + scalar_observable_names() + ")");
  if (obs == "reverse_yield_stress" && sc.setup.strain_path.size() < 2) e.fail("observable", "reverse_yield_stress needs a scene whose strain path reverses");
  if ((obs == "r_value" || obs == "yield_stress") && sc.setup.kind != scene::MaterialPointKind::tensile)
    e.fail("observable", "r_value and yield_stress need a tensile scene");
  return obs;
}

// The point weights of weight_column (if e names one) in the data file.
std::vector<double> point_weights(const io::TomlTable& e, const MeasurementTable& table) {
  if (!e.has("weight_column")) return {};
  const std::string column = e.string("weight_column");
  std::vector<double> w = table.column(column);
  for (double v : w)
    if (!(v >= 0)) throw InputError(table.file, "column " + column, format_number(v), "point weights must be >= 0");
  return w;
}

// A scalar [[experiment]] (an observable of a material-point scene against a value).
std::unique_ptr<Experiment> scalar_experiment(const io::TomlTable& e, MaterialPointExperimentBase b) {
  ScalarExperimentSpec s;
  s.name = b.name;
  s.observable = scalar_observable_of(e, b.scene);
  s.scene = std::move(b.scene);
  s.value = e.number("value");
  s.noise = b.noise;
  s.weight = b.weight;
  s.source = e.string("source", "");
  return make_scalar_experiment(std::move(s));
}

// The scene inputs a row of a table of scalars may set: the real [scene] keys fits may vary.
std::vector<const io::InputInfo*> row_inputs(scene::MaterialPointKind kind) {
  std::vector<const io::InputInfo*> out;
  for (const auto& i : scene::material_point_inputs(kind).infos())
    if (i.table() == "scene" && i.variable && i.type == io::InputType::real) out.push_back(&i);
  return out;
}

// The input of the data column x (a key of [scene], e.g. angle); fails on key x.
const io::InputInfo& row_input(const io::TomlTable& e, const scene::MaterialPointScene& sc, const std::string& x) {
  std::string known;
  for (const io::InputInfo* i : row_inputs(sc.setup.kind)) {
    if (i->key() == x) return *i;
    known += (known.empty() ? "" : ", ") + i->key();
  }
  e.fail("x", "not an input of scene kind " + scene::to_string(sc.setup.kind) + " a row can set (known: " + known + ")");
}

// A table of scalars: observable, data, x (the column of a scene input, default angle).
std::unique_ptr<Experiment> scalar_table_experiment(const io::TomlTable& e, const std::string& path, MaterialPointExperimentBase b) {
  ScalarTableExperimentSpec s;
  s.name = b.name;
  s.observable = scalar_observable_of(e, b.scene);
  s.x = e.string("x", "angle");
  const io::InputInfo& input = row_input(e, b.scene, s.x);
  if (e.has("angle") && s.x == "angle") e.fail("angle", "the data's column angle sets each row's angle: give one or the other");
  const auto table = read_measurement_csv(resolve_path(path, e.string("data")));
  s.xs = table.column(s.x);
  s.ys = table.column(s.observable);
  s.x_unit = table.units.at(s.x);
  s.y_unit = table.units.at(s.observable);
  const bool same_unit = s.x_unit.empty() || s.x_unit == input.unit || (input.unit.empty() && s.x_unit == "-");
  if (!same_unit)
    throw InputError(table.file, "column " + s.x, s.x_unit, "a unit other than the scene input's (" + input.name + " is in " + input.unit + ")");
  if (s.x_unit.empty()) s.x_unit = input.unit;
  s.point_weights = point_weights(e, table);
  const auto& inputs = scene::material_point_inputs(b.scene.setup.kind);
  for (std::size_t i = 0; i < s.xs.size(); ++i) {
    scene::MaterialPointScene row = b.scene;
    if (const std::string why = inputs.set(row, input.name, s.xs[i]); !why.empty())
      throw InputError(table.file, "column " + s.x, format_number(s.xs[i]), input.name + " " + why + " (row " + std::to_string(i + 1) + ")");
    s.setups.push_back(row.setup);
  }
  s.noise = b.noise;
  s.noise_relative = b.noise_relative;
  s.weight = b.weight;
  s.source = e.string("source", "");
  return make_scalar_table_experiment(std::move(s));
}

// A curve [[experiment]]: a column of a measurement CSV against a simulated curve's.
std::unique_ptr<Experiment> curve_experiment(const io::TomlTable& e, const std::string& path, MaterialPointExperimentBase b) {
  CurveExperimentSpec c;
  c.name = b.name;
  c.scene = std::move(b.scene);
  c.noise = b.noise;
  c.noise_relative = b.noise_relative;
  c.weight = b.weight;
  c.x = e.string("x", "strain");
  c.y = e.string("y", "stress");
  scene::CurvePoint<double> probe;
  if (!scene::curve_abscissa(probe, c.x)) e.fail("x", std::string("not an abscissa of a simulated curve (known: ") + scene::curve_abscissa_names() + ")");
  if (!scene::curve_response(probe, c.y)) e.fail("y", std::string("not a column of a simulated curve (known: ") + scene::curve_response_names() + ")");
  auto table = read_measurement_csv(resolve_path(path, e.string("data")));
  table.column(c.x);  // a missing column named first
  table.column(c.y);
  convert_column(table, c.x, scene::curve_column_unit(c.x));  // e.g. strain [%] to a fraction
  convert_column(table, c.y, scene::curve_column_unit(c.y));
  c.xs = table.column(c.x);
  c.ys = table.column(c.y);
  c.x_unit = table.units.at(c.x);
  c.y_unit = table.units.at(c.y);
  c.point_weights = point_weights(e, table);
  bool monotone = true;
  const auto [x_lo, x_hi] = abscissa_range(c.scene.setup, c.x, &monotone);
  if (!monotone) e.fail("x", "the scene's strain reverses: use x = \"cumulative_strain\" (or \"increment\") for curves that reverse");
  for (std::size_t i = 0; i < c.xs.size(); ++i) {
    if (i > 0 && !(c.xs[i] > c.xs[i - 1]))
      throw InputError(table.file, "column " + c.x, format_number(c.xs[i]), "abscissa must increase strictly (row " + std::to_string(i + 1) + ")");
    if (c.xs[i] < x_lo - 1e-12 || c.xs[i] > x_hi + 1e-12)
      throw InputError(table.file, "column " + c.x, format_number(c.xs[i]),
                       "outside the simulated range [" + format_number(x_lo) + ", " + format_number(x_hi) + "] of scene " + c.scene.name);
  }
  return make_curve_experiment(std::move(c));
}

}  // namespace

void allow_material_point_keys(const io::TomlTable& e) {
  if (!e.has("observable")) {
    e.allow_only({"name", "scene", "angle", "data", "x", "y", "noise", "noise_relative", "weight", "weight_column"});
  } else if (!e.has("data")) {
    e.allow_only({"name", "scene", "angle", "observable", "value", "noise", "weight", "source"});
  } else {
    if (e.has("value")) e.fail("value", "a table of scalars (observable and data) takes its values from the data file's column named after the observable");
    if (e.has("y")) e.fail("y", "a table of scalars compares the data file's column named after the observable");
    e.allow_only({"name", "scene", "angle", "observable", "data", "x", "noise", "noise_relative", "weight", "weight_column", "source"});
  }
}

scene::MaterialPointScene read_experiment_scene(const io::TomlTable& e, const std::string& scene_path) {
  scene::MaterialPointScene sc;
  try {
    sc = scene::read_material_point_scene(scene_path, scene::AbsentMaterial::no_card);
  } catch (const io::InputError& err) {
    throw scene::with_kind_hint(err, scene_path, scene::scene_kind_of_file(scene_path));
  }
  if (!e.has("angle")) return sc;
  if (e.value_text("angle").rfind('[', 0) == 0)
    e.fail("angle", "one angle per experiment; for several, a table of scalars (data = FILE with a column angle, x = \"angle\")");
  if (const std::string why = scene::material_point_inputs(sc.setup.kind).set(sc, "scene.angle", e.number("angle")); !why.empty())
    e.fail("angle", why);
  return sc;
}

std::unique_ptr<Experiment> read_material_point_experiment(const io::TomlTable& e, const std::string& path, MaterialPointExperimentBase base) {
  if (e.has("observable") && e.has("data")) return scalar_table_experiment(e, path, std::move(base));
  if (e.has("observable")) return scalar_experiment(e, std::move(base));
  return curve_experiment(e, path, std::move(base));
}

}  // namespace spifit::inverse
