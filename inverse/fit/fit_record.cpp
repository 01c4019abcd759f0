#include "inverse/fit/fit_record.hpp"

#include "forward/io/input_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace spifit::inverse {

using nlohmann::json;

namespace {

constexpr double kNaN = FitRecord::kNaN;

// ---------------------------------------------------------------- writing

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json numbers_json(const std::vector<double>& values) {
  json a = json::array();
  for (double v : values) a.push_back(number_or_null(v));
  return a;
}

json interval_json(double lo, double hi) { return json::array({number_or_null(lo), number_or_null(hi)}); }

json parameter_json(const FitRecord::Parameter& p) {
  json pj{{"value", number_or_null(p.value)}, {"initial", number_or_null(p.initial)}, {"lower", number_or_null(p.lower)},
          {"upper", number_or_null(p.upper)}, {"log_scale", p.log_scale}};
  if (p.has_uncertainty) {
    pj["std_error"] = number_or_null(p.std_error);
    pj["ci95"] = interval_json(p.ci95_lower, p.ci95_upper);
    pj["identifiable"] = p.identifiable;
  }
  return pj;
}

json uncertainty_json(const FitRecord::UncertaintySummary& u) {
  json uj{{"sse", number_or_null(u.sse)}, {"sigma2", number_or_null(u.sigma2)},
          {"t_quantile_975", number_or_null(u.t_quantile_975)}, {"singular_values_scaled", numbers_json(u.singular_values_scaled)},
          {"condition_number", number_or_null(u.condition_number)}};
  if (std::isfinite(u.relative_offset)) uj["relative_offset"] = u.relative_offset;
  if (u.residuals) uj["residuals"] = *u.residuals;
  if (u.parameters) uj["parameters"] = *u.parameters;
  if (u.dof) uj["dof"] = *u.dof;
  return uj;
}

json per_experiment_json(const std::vector<FitRecord::Alone>& alone) {
  json pe = json::array();
  for (const auto& a : alone) {
    json params = json::object();
    for (const auto& v : a.parameters) {
      params[v.parameter] = {{"value", number_or_null(v.value)}, {"ci95", interval_json(v.ci95_lower, v.ci95_upper)},
                             {"identifiable", v.identifiable}};
    }
    pe.push_back({{"experiment", a.experiment}, {"usable", a.usable}, {"parameters", params}});
  }
  return pe;
}

json multistart_json(const FitRecord::MultiStart& ms) {
  json sols = json::array();
  for (const auto& s : ms.solutions) {
    sols.push_back({{"usable", s.usable}, {"cost", number_or_null(s.cost)}, {"start", numbers_json(s.start)}, {"values", numbers_json(s.values)}});
  }
  json spread = json::object();
  for (const auto& s : ms.spread_at_best_cost) spread[s.parameter] = {{"min", number_or_null(s.min)}, {"max", number_or_null(s.max)}};
  return {{"starts", ms.starts}, {"best_start", ms.best_start}, {"starts_at_best_cost", ms.starts_at_best_cost},
          {"spread_at_best_cost", spread}, {"solutions", sols}};
}

json experiment_json(const FitRecord::Experiment& e, const std::vector<FitRecord::Parameter>& parameters) {
  json ej{{"name", e.name}, {"kind", e.kind}, {"points", e.points}, {"cost", number_or_null(e.cost)}, {"rms", number_or_null(e.rms)},
          {"scale", number_or_null(e.scale)}, {"weight", number_or_null(e.weight)}, {"x", e.x}, {"y", e.y}, {"x_unit", e.x_unit},
          {"y_unit", e.y_unit}, {"data_file", e.data_file}};
  if (e.noise_given) ej["noise_given"] = *e.noise_given;
  if (e.noise_points) {
    ej["noise_rms"] = number_or_null(e.noise_rms);
    ej["noise_points"] = *e.noise_points;
  }
  if (!e.x_words.empty()) ej["x_words"] = e.x_words;
  if (!e.y_words.empty()) ej["y_words"] = e.y_words;
  if (!e.information_share.empty()) {
    json shares = json::object();
    for (std::size_t k = 0; k < e.information_share.size() && k < parameters.size(); ++k)
      shares[parameters[k].name] = number_or_null(e.information_share[k]);
    ej["information_share"] = shares;
  }
  if (e.evaluations) ej["evaluations"] = *e.evaluations;
  if (!e.jacobian.empty()) ej["jacobian"] = e.jacobian;
  if (e.scene_runs) {
    ej["scene_runs"] = *e.scene_runs;
    ej["run_seconds"] = number_or_null(e.run_seconds);
  }
  return ej;
}

json runs_by_scene_json(const std::vector<FitRecord::SceneFile>& files) {
  json a = json::array();
  for (const auto& f : files) {
    a.push_back({{"scene", f.scene}, {"runs", f.runs}, {"failures", f.failures}, {"retried", f.retried},
                 {"seconds", number_or_null(f.seconds)}, {"median_seconds", number_or_null(f.median_seconds)}});
  }
  return a;
}

// ---------------------------------------------------------------- reading

// Errors name the file, the key path and (shortened) the offending value.
[[noreturn]] void bad(const std::string& file, const std::string& key, const json& value, const std::string& what) {
  std::string v = value.is_null() ? std::string() : value.dump();
  if (v.size() > 60) v = v.substr(0, 57) + "...";
  throw io::InputError(file, key, v, what);
}

// The member key of obj, or nullptr when obj is no object, lacks it or holds null there.
const json* member(const json& obj, const std::string& key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() || it->is_null() ? nullptr : &*it;
}

// Lenient: the boolean at key, or fallback when it is absent or not a boolean.
bool flag(const json& obj, const std::string& key, bool fallback) {
  const json* v = member(obj, key);
  return v && v->is_boolean() ? v->get<bool>() : fallback;
}

// Strict readers: absent or null gives NaN / empty; another type is an error naming path + key.
struct Reader {
  std::string file;

  double number(const json& obj, const std::string& key, const std::string& path) const {
    const json* v = member(obj, key);
    if (!v) return kNaN;
    if (!v->is_number()) bad(file, path + key, *v, "expected a number");
    return v->get<double>();
  }
  std::optional<long> whole(const json& obj, const std::string& key, const std::string& path) const {
    const double v = number(obj, key, path);
    if (std::isnan(v)) return std::nullopt;
    if (v != std::floor(v) || std::abs(v) > 1e15) bad(file, path + key, obj.at(key), "expected a whole number");
    return static_cast<long>(v);
  }
  std::string text(const json& obj, const std::string& key, const std::string& path) const {
    const json* v = member(obj, key);
    if (!v) return {};
    if (!v->is_string()) bad(file, path + key, *v, "expected a string");
    return v->get<std::string>();
  }
  std::vector<double> numbers(const json& obj, const std::string& key, const std::string& path) const {
    std::vector<double> out;
    const json* v = member(obj, key);
    if (!v) return out;
    if (!v->is_array()) bad(file, path + key, *v, "expected an array of numbers");
    for (const auto& e : *v) {
      if (e.is_null()) out.push_back(kNaN);
      else if (e.is_number()) out.push_back(e.get<double>());
      else bad(file, path + key, e, "expected an array of numbers");
    }
    return out;
  }
  // [lo, hi] at key; NaN both unless it holds exactly two entries.
  void interval(const json& obj, const std::string& key, const std::string& path, double* lo, double* hi) const {
    const auto ci = numbers(obj, key, path);
    if (ci.size() == 2) {
      *lo = ci[0];
      *hi = ci[1];
    }
  }
};

std::optional<int> as_int(const std::optional<long>& v) {
  return v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
}

void read_summary(const Reader& r, const json& j, FitRecord& rec) {
  rec.name = r.text(j, "fit", "");
  rec.fit_file = r.text(j, "fit_file", "");
  rec.algorithm = r.text(j, "algorithm", "");
  rec.termination = r.text(j, "termination", "");
  rec.spifit_version = r.text(j, "spifit_version", "");
  rec.cost_definition = r.text(j, "cost_definition", "");
  if (const json* u = member(j, "usable"); u && u->is_boolean()) rec.usable = u->get<bool>();
  if (const json* s = member(j, "seed"); s && s->is_number()) rec.seed = s->get<unsigned>();
  rec.iterations = as_int(r.whole(j, "iterations", ""));
  rec.forward_runs = r.whole(j, "forward_runs", "");
  rec.scene_runs = r.whole(j, "scene_runs", "");
  if (const json* f = member(j, "failed_runs"); f && f->is_array()) {
    for (const auto& e : *f) {
      if (!e.is_object()) continue;
      rec.failed_runs.push_back({e.value("scene", ""), e.value("point", ""), e.value("message", ""), e.value("recovered", false)});
    }
  }
  rec.wall_seconds = r.number(j, "wall_seconds", "");
  rec.cost_initial = r.number(j, "cost_initial", "");
  rec.cost_final = r.number(j, "cost_final", "");
  rec.cost_history = r.numbers(j, "cost_history", "");
}

void read_runs_by_scene(const Reader& r, const json& j, FitRecord& rec) {
  const json* a = member(j, "runs_by_scene");
  if (!a) return;
  if (!a->is_array()) bad(r.file, "runs_by_scene", *a, "expected an array of objects");
  int index = 0;
  for (const auto& fj : *a) {
    const std::string at = "runs_by_scene[" + std::to_string(index++) + "].";
    if (!fj.is_object()) bad(r.file, at.substr(0, at.size() - 1), fj, "expected an object");
    FitRecord::SceneFile f;
    f.scene = r.text(fj, "scene", at);
    f.runs = r.whole(fj, "runs", at).value_or(0);
    f.failures = r.whole(fj, "failures", at).value_or(0);
    f.retried = r.whole(fj, "retried", at).value_or(0);
    f.seconds = r.number(fj, "seconds", at);
    f.median_seconds = r.number(fj, "median_seconds", at);
    rec.runs_by_scene.push_back(f);
  }
}

void read_correlation(const Reader& r, const json& j, FitRecord& rec) {
  const json* c = member(j, "correlation");
  if (!c || !c->is_object()) return;
  if (const json* names = member(*c, "names"); names && names->is_array()) {
    for (const auto& n : *names) {
      if (!n.is_string()) bad(r.file, "correlation.names", n, "expected strings");
      rec.correlation.names.push_back(n.get<std::string>());
    }
  }
  if (const json* matrix = member(*c, "matrix"); matrix && matrix->is_array()) {
    for (const auto& row : *matrix) {
      if (!row.is_array()) bad(r.file, "correlation.matrix", row, "expected an array of rows");
      std::vector<double> values;
      for (const auto& v : row) values.push_back(v.is_number() ? v.get<double>() : kNaN);
      rec.correlation.matrix.push_back(values);
    }
  }
}

FitRecord::Parameter read_parameter(const Reader& r, const std::string& name, const json& pj) {
  const std::string at = "parameters." + name + ".";
  if (!pj.is_object()) bad(r.file, "parameters." + name, pj, "expected an object");
  FitRecord::Parameter p;
  p.name = name;
  p.value = r.number(pj, "value", at);
  p.initial = r.number(pj, "initial", at);
  p.lower = r.number(pj, "lower", at);
  p.upper = r.number(pj, "upper", at);
  p.log_scale = flag(pj, "log_scale", false);
  if (pj.contains("std_error") || pj.contains("identifiable")) {
    p.has_uncertainty = true;
    p.std_error = r.number(pj, "std_error", at);
    r.interval(pj, "ci95", at, &p.ci95_lower, &p.ci95_upper);
    p.identifiable = flag(pj, "identifiable", true);
  }
  return p;
}

// Parameters in the order of the fit (correlation.names), then any others.
void read_parameters(const Reader& r, const json& j, FitRecord& rec) {
  const json& params = j.at("parameters");
  std::vector<std::string> order;
  for (const auto& n : rec.correlation.names) {
    if (params.contains(n) && std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
  }
  for (const auto& [n, v] : params.items()) {
    if (std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
  }
  for (const auto& n : order) rec.parameters.push_back(read_parameter(r, n, params.at(n)));
  if (const json* fixed = member(j, "fixed"); fixed && fixed->is_object()) {
    for (const auto& [n, v] : fixed->items()) {
      FitRecord::FixedParameter f;
      f.name = n;
      if (v.is_number()) f.value = v.get<double>();
      else if (v.is_string()) f.expression = v.get<std::string>();
      else if (!v.is_null()) f.expression = v.dump();
      rec.fixed.push_back(f);
    }
  }
}

void read_uncertainty(const Reader& r, const json& j, FitRecord& rec) {
  const json* u = member(j, "uncertainty");
  if (!u || !u->is_object()) return;
  const std::string at = "uncertainty.";
  auto& s = rec.uncertainty;
  s.residuals = as_int(r.whole(*u, "residuals", at));
  s.parameters = as_int(r.whole(*u, "parameters", at));
  s.dof = as_int(r.whole(*u, "dof", at));
  s.sse = r.number(*u, "sse", at);
  s.sigma2 = r.number(*u, "sigma2", at);
  s.t_quantile_975 = r.number(*u, "t_quantile_975", at);
  s.condition_number = r.number(*u, "condition_number", at);
  if (member(*u, "relative_offset")) s.relative_offset = r.number(*u, "relative_offset", at);
  s.singular_values_scaled = r.numbers(*u, "singular_values_scaled", at);
}

void read_texts(const Reader& r, const json& j, const char* key, std::vector<std::string>& into) {
  const json* a = member(j, key);
  if (!a) return;
  if (!a->is_array()) bad(r.file, key, *a, "expected an array of strings");
  for (const auto& w : *a) into.push_back(w.is_string() ? w.get<std::string>() : w.dump());
}

void read_per_experiment(const Reader& r, const json& j, FitRecord& rec) {
  const json* pe = member(j, "per_experiment");
  if (!pe || !pe->is_array()) return;
  int index = 0;
  for (const auto& aj : *pe) {
    const std::string at = "per_experiment[" + std::to_string(index++) + "].";
    if (!aj.is_object()) bad(r.file, at.substr(0, at.size() - 1), aj, "expected an object");
    FitRecord::Alone a;
    a.experiment = r.text(aj, "experiment", at);
    a.usable = flag(aj, "usable", true);
    if (const json* params = member(aj, "parameters"); params && params->is_object()) {
      for (const auto& [n, pj] : params->items()) {
        if (!pj.is_object()) continue;
        const std::string pat = at + "parameters." + n + ".";
        FitRecord::AloneValue v;
        v.parameter = n;
        v.value = r.number(pj, "value", pat);
        r.interval(pj, "ci95", pat, &v.ci95_lower, &v.ci95_upper);
        v.identifiable = flag(pj, "identifiable", true);
        a.parameters.push_back(v);
      }
    }
    rec.per_experiment.push_back(a);
  }
}

// Lenient: multistart is optional detail and never makes a fit.json unreadable.
std::vector<double> lenient_numbers(const json& obj, const char* key) {
  std::vector<double> out;
  const json* a = member(obj, key);
  if (!a || !a->is_array()) return out;
  for (const auto& v : *a) out.push_back(v.is_number() ? v.get<double>() : kNaN);
  return out;
}

void read_multistart(const json& j, FitRecord& rec) {
  const json* m = member(j, "multistart");
  if (!m || !m->is_object()) return;
  auto integer = [&](const char* k) {
    const json* v = member(*m, k);
    return v && v->is_number() ? v->get<int>() : -1;
  };
  if (integer("starts") <= 1) return;
  auto& ms = rec.multistart;
  ms.starts = integer("starts");
  ms.best_start = integer("best_start");
  ms.starts_at_best_cost = integer("starts_at_best_cost");
  if (const json* spread = member(*m, "spread_at_best_cost"); spread && spread->is_object()) {
    for (const auto& [n, sj] : spread->items()) {
      if (!sj.is_object()) continue;
      FitRecord::Spread s;
      s.parameter = n;
      if (const json* lo = member(sj, "min"); lo && lo->is_number()) s.min = lo->get<double>();
      if (const json* hi = member(sj, "max"); hi && hi->is_number()) s.max = hi->get<double>();
      ms.spread_at_best_cost.push_back(s);
    }
  }
  if (const json* sols = member(*m, "solutions"); sols && sols->is_array()) {
    for (const auto& sj : *sols) {
      if (!sj.is_object()) continue;
      FitRecord::StartSolution s;
      s.usable = flag(sj, "usable", false);
      if (const json* c = member(sj, "cost"); c && c->is_number()) s.cost = c->get<double>();
      s.start = lenient_numbers(sj, "start");
      s.values = lenient_numbers(sj, "values");
      ms.solutions.push_back(s);
    }
  }
}

void read_experiments(const Reader& r, const json& j, FitRecord& rec) {
  int index = 0;
  for (const auto& ej : j.at("experiments")) {
    const std::string at = "experiments[" + std::to_string(index++) + "].";
    if (!ej.is_object()) bad(r.file, at.substr(0, at.size() - 1), ej, "expected an object");
    FitRecord::Experiment e;
    e.name = r.text(ej, "name", at);
    if (e.name.empty()) bad(r.file, at + "name", json(), "missing experiment name");
    e.kind = r.text(ej, "kind", at);
    e.x = r.text(ej, "x", at);
    e.y = r.text(ej, "y", at);
    e.x_unit = r.text(ej, "x_unit", at);
    e.y_unit = r.text(ej, "y_unit", at);
    if (member(ej, "x_words")) e.x_words = r.text(ej, "x_words", at);
    if (member(ej, "y_words")) e.y_words = r.text(ej, "y_words", at);
    e.data_file = r.text(ej, "data_file", at);
    e.points = static_cast<int>(r.whole(ej, "points", at).value_or(0));
    e.cost = r.number(ej, "cost", at);
    e.rms = r.number(ej, "rms", at);
    e.scale = r.number(ej, "scale", at);
    const double w = r.number(ej, "weight", at);
    e.weight = std::isfinite(w) ? w : 1.0;
    if (const json* n = member(ej, "noise_given"); n && n->is_boolean()) e.noise_given = n->get<bool>();
    if (member(ej, "noise_points")) {
      e.noise_rms = r.number(ej, "noise_rms", at);
      e.noise_points = static_cast<int>(r.whole(ej, "noise_points", at).value_or(0));
    }
    if (const json* shares = member(ej, "information_share")) {
      if (!shares->is_object()) bad(r.file, at + "information_share", *shares, "expected an object of parameter names and numbers");
      for (const auto& q : rec.parameters) e.information_share.push_back(r.number(*shares, q.name, at + "information_share."));
    }
    e.evaluations = r.whole(ej, "evaluations", at);
    e.jacobian = r.text(ej, "jacobian", at);
    e.scene_runs = r.whole(ej, "scene_runs", at);
    e.run_seconds = r.number(ej, "run_seconds", at);
    rec.experiments.push_back(std::move(e));
  }
}

}  // namespace

json to_json(const FitRecord& rec) {
  json j;
  j["spifit_version"] = rec.spifit_version;
  j["fit"] = rec.name;
  j["fit_file"] = rec.fit_file;
  j["algorithm"] = rec.algorithm;
  if (rec.seed) j["seed"] = *rec.seed;
  j["termination"] = rec.termination;
  if (rec.usable) j["usable"] = *rec.usable;
  if (!rec.not_usable.empty()) j["not_usable_because"] = rec.not_usable;
  if (rec.iterations) j["iterations"] = *rec.iterations;
  if (rec.forward_runs) j["forward_runs"] = *rec.forward_runs;
  if (rec.scene_runs) {
    j["scene_runs"] = *rec.scene_runs;
    json failed = json::array();
    for (const auto& f : rec.failed_runs)
      failed.push_back({{"scene", f.scene}, {"point", f.point}, {"message", f.message}, {"recovered", f.recovered}});
    j["failed_runs"] = failed;
    j["runs_by_scene"] = runs_by_scene_json(rec.runs_by_scene);
  }
  j["wall_seconds"] = number_or_null(rec.wall_seconds);
  j["cost_definition"] = rec.cost_definition;
  j["cost_initial"] = number_or_null(rec.cost_initial);
  j["cost_final"] = number_or_null(rec.cost_final);
  j["cost_history"] = numbers_json(rec.cost_history);
  json params = json::object();
  for (const auto& p : rec.parameters) params[p.name] = parameter_json(p);
  j["parameters"] = params;
  json fixed = json::object();
  for (const auto& f : rec.fixed) fixed[f.name] = f.expression.empty() ? number_or_null(f.value) : json(f.expression);
  j["fixed"] = fixed;
  json matrix = json::array();
  for (const auto& row : rec.correlation.matrix) matrix.push_back(numbers_json(row));
  j["correlation"] = {{"names", rec.correlation.names}, {"matrix", matrix}};
  j["uncertainty"] = uncertainty_json(rec.uncertainty);
  j["warnings"] = rec.warnings;
  if (!rec.notes.empty()) j["notes"] = rec.notes;
  j["conflicts"] = rec.conflicts;
  j["per_experiment"] = per_experiment_json(rec.per_experiment);
  if (rec.multistart.starts > 1) j["multistart"] = multistart_json(rec.multistart);
  json ex = json::array();
  for (const auto& e : rec.experiments) ex.push_back(experiment_json(e, rec.parameters));
  j["experiments"] = ex;
  return j;
}

FitRecord fit_record_from_json(const json& j, const std::string& file) {
  if (!j.is_object()) throw io::InputError(file, "", "", "not a fit.json: the top level is not an object");
  const Reader r{file};
  FitRecord rec;
  try {
    if (!j.contains("parameters") || !j["parameters"].is_object()) {
      bad(file, "parameters", j.value("parameters", json()), "missing or not an object: not a fit.json");
    }
    if (!j.contains("experiments") || !j["experiments"].is_array()) {
      bad(file, "experiments", j.value("experiments", json()), "missing or not an array: not a fit.json");
    }
    read_summary(r, j, rec);
    read_runs_by_scene(r, j, rec);
    read_correlation(r, j, rec);
    read_parameters(r, j, rec);
    read_uncertainty(r, j, rec);
    read_texts(r, j, "not_usable_because", rec.not_usable);
    read_texts(r, j, "warnings", rec.warnings);
    read_texts(r, j, "notes", rec.notes);
    read_texts(r, j, "conflicts", rec.conflicts);
    read_per_experiment(r, j, rec);
    read_multistart(j, rec);
    read_experiments(r, j, rec);
  } catch (const json::exception& e) {
    throw io::InputError(file, "", "", std::string("unexpected content: ") + e.what());
  }
  return rec;
}

FitRecord read_fit_record(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw io::InputError(file, "", "", "cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  json j;
  try {
    j = json::parse(ss.str());
  } catch (const json::exception& e) {
    throw io::InputError(file, "", "", std::string("not valid JSON: ") + e.what());
  }
  return fit_record_from_json(j, file);
}

}  // namespace spifit::inverse
