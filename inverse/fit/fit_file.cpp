#include "inverse/fit/fit_file.hpp"

#include "forward/io/toml_reader.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "forward/scenes/sensitivity_refusal.hpp"
#include "inverse/experiments/fe_experiment_file.hpp"
#include "inverse/experiments/material_point_experiment_file.hpp"
#include "inverse/experiments/measurement.hpp"
#include "inverse/fit/fit_algorithms.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace spifit::inverse {

namespace fs = std::filesystem;
using io::format_number;
using io::InputError;

namespace {

// scene_info: the named input of the FE scenes for a scene-input parameter, else null.
ParameterSpec read_parameter(const io::TomlTable& t, const std::string& name, double current, const io::InputInfo* scene_info) {
  t.allow_only({"initial", "lower", "upper", "fixed", "log"});
  ParameterSpec p;
  p.name = name;
  p.scene_input = scene_info != nullptr;
  p.initial = t.number("initial", current);
  if (scene_info) {
    for (const char* k : {"initial", "lower", "upper"}) {
      if (!t.has(k)) continue;
      if (const std::string why = scene_info->check(t.number(k)); !why.empty()) t.fail(k, why);
    }
  }
  p.fixed = t.boolean("fixed", false);
  p.log_scale = t.boolean("log", false);
  if (!p.fixed) {
    p.lower = t.number("lower");
    p.upper = t.number("upper");
    if (!(p.lower < p.upper)) t.fail("upper", "must be > lower = " + format_number(p.lower));
    if (p.initial < p.lower || p.initial > p.upper)
      t.fail(t.has("initial") ? "initial" : "lower", "initial value " + format_number(p.initial) + " lies outside [lower, upper]");
    if (p.log_scale && !(p.lower > 0)) t.fail("lower", "log-scaled parameters need lower > 0");
  } else {
    p.lower = p.upper = p.initial;
  }
  return p;
}

}  // namespace

namespace {

// [fit]: name, starting card, optimiser settings. Returns the card; *normalise = normalise_hill.
material::MaterialCard read_fit_table(const io::TomlTable& root, const std::string& path, FitProblem& fp, bool* normalise) {
  const auto ft = root.table("fit");
  if (!ft) root.fail("fit", "required table [fit] is missing");
  ft->allow_only({"name", "description", "card", "normalise_hill", "algorithm", "max_iterations", "function_tolerance",
                  "parameter_tolerance", "gradient_tolerance", "offset_tolerance", "per_experiment", "multistart", "run_time_limit", "jacobian"});
  fp.multistart = ft->integer("multistart", 1);
  if (fp.multistart < 1 || fp.multistart > 10000) ft->fail("multistart", "must lie in [1, 10000]");
  fp.per_experiment = ft->boolean("per_experiment", false);  // default: see read_fit_file
  fp.name = ft->string("name", fs::path(path).stem().string());
  fp.description = ft->string("description", "");
  const std::string card_path = resolve_path(path, ft->string("card"));
  if (!fs::exists(card_path)) ft->fail("card", "starting card not found at " + card_path);
  auto card = material::load_material_card(card_path);
  // Hill's normalisation G + H = 2 only where Hill 1948 is the card's yield function.
  const bool hill = !card.params.yield.active();
  *normalise = ft->boolean("normalise_hill", hill);
  if (*normalise && !hill)
    ft->fail("normalise_hill", "the starting card's yield function is " + material::yield_function(card.params.yield.law).name + ", not Hill 1948");
  auto& st = fp.settings;
  st.algorithm = ft->string("algorithm", st.algorithm);
  if (!is_fit_algorithm(st.algorithm)) ft->fail("algorithm", "unknown algorithm (known: " + fit_algorithm_names() + ")");
  st.max_iterations = ft->integer("max_iterations", st.max_iterations);
  if (st.max_iterations < 1) ft->fail("max_iterations", "must be >= 1");
  st.function_tolerance = ft->number("function_tolerance", st.function_tolerance);
  st.parameter_tolerance = ft->number("parameter_tolerance", st.parameter_tolerance);
  st.gradient_tolerance = ft->number("gradient_tolerance", st.gradient_tolerance);
  st.offset_tolerance = ft->number("offset_tolerance", st.offset_tolerance);
  if (ft->has("offset_tolerance") && st.offset_tolerance > 0.0 && is_nlopt_algorithm(st.algorithm))
    ft->fail("offset_tolerance", "stops Ceres's algorithms (levenberg_marquardt, dogleg) only, not " + st.algorithm);
  st.jacobian = ft->string("jacobian", "");
  if (ft->has("jacobian") && st.jacobian != "exact" && st.jacobian != "central")
    ft->fail("jacobian", "must be \"exact\" (through runs with sensitivities) or \"central\" (differences of whole runs)");
  st.run_time_limit = ft->number("run_time_limit", 0.0);
  if (!(st.run_time_limit >= 0.0)) ft->fail("run_time_limit", "must be >= 0 s (0: no limit)");
  for (const char* k : {"function_tolerance", "parameter_tolerance", "gradient_tolerance", "offset_tolerance"}) {
    if (ft->has(k) && !(ft->number(k) >= 0)) ft->fail(k, "must be >= 0");
  }
  return card;
}

// The named input `name` of every FE scene of the fit (a number a fit may vary), or null when
// no FE scene has it; fails on `key` when only some have it.
const io::InputInfo* scene_input(const io::TomlTable& pt, const std::string& name, const std::vector<const scene::Scene*>& fe_scenes) {
  const io::InputInfo* found = nullptr;
  for (const scene::Scene* sc : fe_scenes) {
    const scene::SceneKind* kind = scene::find_scene_kind(sc->kind());
    const io::InputInfo* info = nullptr;
    for (const auto& i : kind->inputs)
      if (i.name == name && i.variable && i.type == io::InputType::real) info = &i;
    if (!info && found) pt.fail(name, "scene " + sc->file() + " (kind " + sc->kind() + ") has no input a fit can vary by this name");
    if (info && !found && sc != fe_scenes.front()) pt.fail(name, "scene " + fe_scenes.front()->file() + " has no input a fit can vary by this name");
    found = info;
  }
  return found;
}

// What a fit may vary, for messages: the parameters of the card's laws and the FE scenes' real
// inputs.
std::string fittable_names(const material::MaterialCard& card, const std::vector<const scene::Scene*>& fe_scenes) {
  std::string known;
  for (const auto& in : material::material_inputs())
    if (material::holds_input(card.params, in)) known += (known.empty() ? "" : ", ") + in.info.name;
  if (fe_scenes.empty()) return known + "; scene inputs such as contact.friction with an FE scene";
  for (const auto& i : scene::find_scene_kind(fe_scenes.front()->kind())->inputs)
    if (i.variable && i.type == io::InputType::real) known += ", " + i.name;
  return known;
}

// [parameters."NAME"]: the parameter set over the card and the FE scenes' inputs.
void read_parameters(const io::TomlTable& root, const material::MaterialCard& card, bool normalise, const std::vector<const scene::Scene*>& fe_scenes,
                     FitProblem& fp) {
  std::vector<ParameterSpec> specs;
  const auto pt = root.table("parameters");
  if (!pt) root.fail("parameters", "required table [parameters] is missing");
  for (const auto& name : pt->keys()) {
    const io::InputInfo* info = is_known_parameter(name) ? nullptr : scene_input(*pt, name, fe_scenes);
    if (!is_known_parameter(name) && !info) pt->fail(name, "unknown parameter (known for this card: " + fittable_names(card, fe_scenes) + ")");
    if (name == "hill.H" && normalise) pt->fail(name, "H = 2 - G while [fit] normalise_hill = true; fit hill.G instead");
    if (const material::MaterialInput* in = info ? nullptr : material::find_material_input(name))
      if (const std::string why = material::why_not_held(card.params, *in); !why.empty()) pt->fail(name, why + " (card " + card.file + ")");
    const double current = info ? fe_scenes.front()->input(name) : parameter_value(card, name);
    specs.push_back(read_parameter(*pt->table(name), name, current, info));
    // Every FE scene runs with the scene input at its start and at either bound.
    const ParameterSpec& p = specs.back();
    for (const scene::Scene* sc : info ? fe_scenes : std::vector<const scene::Scene*>{}) {
      for (const auto& [key, v] : {std::pair<const char*, double>{"initial", p.initial}, {"lower", p.lower}, {"upper", p.upper}}) {
        if (const std::string why = sc->clone()->set_input(name, v); !why.empty())
          pt->table(name)->fail(pt->table(name)->has(key) ? key : "initial", "scene " + sc->file() + " cannot run at " + format_number(v) + ": " + why);
      }
    }
  }
  fp.parameters = std::make_unique<ParameterSet>(card, specs, normalise);
  if (fp.parameters->num_free() == 0) root.fail("parameters", "no free parameter (every listed parameter is fixed)");
  if (normalise && std::abs(card.params.G + card.params.H - 2.0) > 1e-12) {
    fp.notes.push_back("normalise_hill: the starting card has G + H = " + format_number(card.params.G + card.params.H) +
                       "; the fit uses H = 2 - G");
  }
}

// How the FE experiments are differentiated: per scene file, exact when every experiment on it
// can take exact derivatives and the scene can be run with sensitivities with respect to every
// free parameter (sensitivity_refusal.hpp); else central differences, or ([fit] jacobian =
// "exact") an error naming the scene and why. Each scene file's runs then carry the derivatives.
void choose_jacobians(const io::TomlTable& root, const std::vector<const scene::Scene*>& fe_scenes, bool from_command_line, FitProblem& fp) {
  if (!fp.scene_runs || fp.settings.jacobian == "central") return;
  const ParameterSet& ps = *fp.parameters;
  std::vector<std::string> names;
  bool h_follows_g = false;
  for (int i : ps.free_indices()) {
    names.push_back(ps.specs()[static_cast<std::size_t>(i)].name);
    h_follows_g = h_follows_g || (ps.normalise_hill() && names.back() == "hill.G");
  }
  std::vector<std::string> done;
  std::size_t next_scene = 0;
  for (const auto& e : fp.experiments) {
    if (e->supports_jets()) continue;
    const scene::Scene& sc = *fe_scenes[next_scene++];
    if (std::find(done.begin(), done.end(), sc.file()) != done.end()) continue;
    done.push_back(sc.file());
    std::string why;
    for (const auto& other : fp.experiments)
      if (other->scene_file() == sc.file() && !other->differentiable() && why.empty())
        why = "experiment " + other->name() + " (" + other->kind() + " " + other->axes().y_name + ") has no exact derivatives yet";
    if (why.empty()) {
      std::unique_ptr<scene::Scene> with_card = sc.clone();
      with_card->card()->params = ps.base().params;
      if (const auto r = scene::sensitivity_refusal(*with_card, names, h_follows_g))
        why = r->key == "--sensitivities" ? r->why : r->key + " = " + r->value + ": " + r->why;
    }
    if (!why.empty()) {
      if (fp.settings.jacobian == "exact" && from_command_line) throw InputError(fp.file, "--jacobian", "exact", "scene " + sc.file() + ": " + why);
      if (fp.settings.jacobian == "exact") root.table("fit")->fail("jacobian", "scene " + sc.file() + ": " + why);
      fp.notes.push_back("central differences for the experiments on scene " + sc.file() + ": " + why + ".");
      continue;
    }
    fp.scene_runs->differentiate(sc.file(), names, h_follows_g);
    for (const auto& other : fp.experiments)
      if (other->scene_file() == sc.file()) other->set_exact_columns(ps.num_free());
  }
}

// The card must stay valid at the start and with each free parameter at either bound (else the
// fit could return a card spifit itself rejects).
void check_card_at_bounds(const std::string& path, const FitProblem& fp) {
  auto check_card = [&](const std::vector<double>& internal, const std::string& key, double value, const std::string& where) {
    try {
      material::validate_material_card(fp.parameters->card_for(internal));
    } catch (const InputError& err) {
      throw InputError(path, key, format_number(value),
                       where + " makes the card invalid (" + err.key() + " = " + err.value() + ": " + err.message() + ")");
    }
  };
  const auto x0 = fp.parameters->initial_internal();
  check_card(x0, "parameters", 0.0, "the initial values");
  const auto lo = fp.parameters->lower_internal(), hi = fp.parameters->upper_internal();
  for (int k = 0; k < fp.parameters->num_free(); ++k) {
    const auto& s = fp.parameters->specs()[fp.parameters->free_indices()[k]];
    for (int side = 0; side < 2; ++side) {
      auto x = x0;
      x[k] = side == 0 ? lo[k] : hi[k];
      check_card(x, "parameters." + s.name + (side == 0 ? ".lower" : ".upper"), side == 0 ? s.lower : s.upper, "this bound");
    }
  }
}

std::unique_ptr<Experiment> read_experiment(const io::TomlTable& e, const std::string& path, const material::MaterialCard& card, FitProblem& fp,
                                            std::vector<const scene::Scene*>& fe_scenes) {
  const std::string scene_path = resolve_path(path, e.string("scene"));
  if (!fs::exists(scene_path)) e.fail("scene", "scene file not found at " + scene_path);
  const scene::SceneKind* kind = scene::find_scene_kind(scene::scene_kind_of_file(scene_path));
  if (!kind) (void)scene::read_scene(scene_path);  // names the unknown kind and the known ones
  const bool fe = !kind->jets;  // FE scenes: experiments on the scene's typed result; Jet scenes: material-point experiments
  if (fe) e.allow_only(fe_experiment_keys());
  else allow_material_point_keys(e);
  std::shared_ptr<const scene::Scene> fe_scene;
  scene::MaterialPointScene sc;
  if (fe) {
    fe_scene = scene::read_scene(scene_path);
    if (!fe_scene->card()) e.fail("scene", "scene kind " + kind->name + " has a material of its own: a fit cannot set its card");
  } else {
    sc = read_experiment_scene(e, scene_path);
  }
  const std::string name = e.string("name", fe ? fe_scene->name() : sc.name);
  if (fe) {
    for (const auto& f : fe_scene->input_files()) fp.input_files.push_back(f);
    for (const auto& w : fe_scene->input_warnings()) {
      const std::string note = "scene " + scene_path + ": " + w;
      if (std::find(fp.notes.begin(), fp.notes.end(), note) == fp.notes.end()) fp.notes.push_back(note);
    }
  } else {
    fp.input_files.push_back(scene_path);
  }
  if (e.has("data")) {
    fp.input_files.push_back(resolve_path(path, e.string("data")));
    fp.data_files.push_back(fp.input_files.back());
  }
  // Names become file names (DIR/experiments/NAME.csv): plain and unique.
  const bool plain = !name.empty() && name[0] != '.' &&
                     std::all_of(name.begin(), name.end(), [](char ch) {
                       return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.';
                     });
  if (!plain) e.fail("name", "experiment names may use letters, digits, _ - . and must not start with '.'");
  for (const auto& other : fp.experiments) {
    if (other->name() == name) e.fail("name", "two experiments have this name");
  }
  const double noise = e.number("noise", 0.0);
  if (noise < 0) e.fail("noise", "must be >= 0 (0: condition by the range of the data)");
  const double noise_relative = e.number("noise_relative", 0.0);
  if (!(noise_relative >= 0.0 && noise_relative < 1.0)) e.fail("noise_relative", "must lie in [0, 1): a fraction of each |y|");
  if (noise_relative > 0.0 && e.has("noise")) e.fail("noise_relative", "give noise (absolute) or noise_relative, not both");
  const double weight = e.number("weight", 1.0);
  if (!(weight > 0)) e.fail("weight", "must be > 0");
  if (fe) {
    if (!fp.scene_runs) fp.scene_runs = std::make_shared<SceneRuns>(card.params, fp.settings.run_time_limit);
    fe_scenes.push_back(fe_scene.get());
    return read_fe_experiment(e, path, FeExperimentBase{name, fe_scene, fp.scene_runs, noise, noise_relative, weight});
  }
  return read_material_point_experiment(e, path, {name, std::move(sc), noise, noise_relative, weight});
}

}  // namespace

namespace {

// The measured values of each experiment against what its scene and the start card make
// plausible (measurement_plausibility.hpp): implausible ones are an input error naming the data
// file, its column and the unit its header gives (or the experiment's value); odd ones a note.
void check_measured_magnitudes(const std::vector<io::TomlTable>& tables, const std::string& path, FitProblem& fp) {
  const ParameterPoint start = fp.parameters->point(fp.parameters->initial_internal().data());
  for (std::size_t i = 0; i < fp.experiments.size() && i < tables.size(); ++i) {
    const Experiment& e = *fp.experiments[i];
    const MagnitudeCheck c = e.check_magnitudes(start);
    if (c.level == 0) continue;
    const io::TomlTable& t = tables[i];
    if (c.level == 1) {
      fp.notes.push_back("experiment " + e.name() + ": " + c.message + ".");
      continue;
    }
    if (!t.has("data")) t.fail("value", c.message);
    const std::string data = resolve_path(path, t.string("data"));
    const std::string column = e.axes().y_name;
    std::string unit;
    try {
      const MeasurementTable m = read_measurement_csv(data);
      if (m.units.count(column)) unit = m.units.at(column);
    } catch (const InputError&) {
    }
    throw InputError(data, "column " + column, unit.empty() ? "(no unit)" : "[" + unit + "]", c.message);
  }
}

}  // namespace

FitSettings fe_fit_settings() {
  FitSettings s;
  s.function_tolerance = 1e-9;
  s.parameter_tolerance = 1e-8;
  s.gradient_tolerance = 1e-10;
  s.offset_tolerance = 1e-3;
  return s;
}

FitProblem read_fit_file(const std::string& path, const std::string& jacobian) {
  if (!jacobian.empty() && jacobian != "exact" && jacobian != "central")
    throw InputError(path, "--jacobian", jacobian, "must be exact (through runs with sensitivities) or central (differences of whole runs)");
  const auto root = io::TomlTable::parse_file(path);
  root.allow_only({"fit", "parameters", "experiment"});
  FitProblem fp;
  fp.file = path;
  bool normalise = true;
  const material::MaterialCard card = read_fit_table(root, path, fp, &normalise);
  if (!jacobian.empty()) fp.settings.jacobian = jacobian;
  fp.input_files = {path, card.file};
  // The experiments first: the FE scenes among them say which scene inputs are parameters.
  const auto exps = root.table_array("experiment");
  std::vector<const scene::Scene*> fe_scenes;
  for (const auto& e : exps) fp.experiments.push_back(read_experiment(e, path, card, fp, fe_scenes));
  const auto ft = root.table("fit");
  // Each experiment fitted alone: cheap with material points only, every FE run again otherwise.
  if (!ft->has("per_experiment")) fp.per_experiment = !fp.scene_runs;
  if (fp.scene_runs) {
    const FitSettings fe = fe_fit_settings();
    if (!ft->has("function_tolerance")) fp.settings.function_tolerance = fe.function_tolerance;
    if (!ft->has("parameter_tolerance")) fp.settings.parameter_tolerance = fe.parameter_tolerance;
    if (!ft->has("gradient_tolerance")) fp.settings.gradient_tolerance = fe.gradient_tolerance;
    if (!ft->has("offset_tolerance")) fp.settings.offset_tolerance = fe.offset_tolerance;
  }
  read_parameters(root, card, normalise, fe_scenes, fp);
  if (exps.empty()) root.fail("experiment", "at least one [[experiment]] is required");
  choose_jacobians(root, fe_scenes, !jacobian.empty(), fp);
  check_card_at_bounds(path, fp);
  check_measured_magnitudes(exps, path, fp);
  return fp;
}

}  // namespace spifit::inverse
