#include "inverse/fit_output.hpp"

#include "forward/io/csv_writer.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace spifit::inverse {

using nlohmann::json;

namespace {
json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
}  // namespace

json fit_result_json(const FitProblem& fp, const FitResult& r) {
  const auto& ps = *fp.parameters;
  const auto& u = r.uncertainty;
  json j;
  j["spifit_version"] = SPIFIT_VERSION;
  j["fit"] = fp.name;
  j["fit_file"] = fp.file;
  j["algorithm"] = r.algorithm;
  j["seed"] = r.seed;
  j["termination"] = r.termination;
  j["usable"] = r.usable;
  j["iterations"] = r.iterations;
  j["forward_runs"] = r.forward_runs;
  j["wall_seconds"] = r.wall_seconds;
  j["cost_definition"] = "1/2 sum of squared conditioned residuals sqrt(w) (simulated - measured) / scale";
  j["cost_initial"] = number_or_null(r.cost_initial);
  j["cost_final"] = number_or_null(r.cost_final);
  j["cost_history"] = r.cost_history;
  json params = json::object();
  for (int k = 0; k < ps.num_free(); ++k) {
    const auto& s = ps.specs()[ps.free_indices()[k]];
    json pj{{"value", r.values[k]}, {"initial", r.initial[k]}, {"lower", s.lower}, {"upper", s.upper}, {"log_scale", s.log_scale}};
    if (k < static_cast<int>(u.std_error.size())) {
      pj["std_error"] = number_or_null(u.std_error[k]);
      pj["ci95"] = {number_or_null(u.ci95_lower[k]), number_or_null(u.ci95_upper[k])};
      pj["identifiable"] = bool(u.identifiable[k]);
    }
    params[s.name] = pj;
  }
  j["parameters"] = params;
  json fixed = json::object();
  for (const auto& s : ps.specs()) if (s.fixed) fixed[s.name] = s.initial;
  if (ps.normalise_hill()) fixed["hill.H"] = "2 - hill.G";
  j["fixed"] = fixed;
  std::vector<std::string> names;
  for (int idx : ps.free_indices()) names.push_back(ps.specs()[idx].name);
  json corr = json::array();
  for (int a = 0; a < u.correlation.rows(); ++a) {
    json row = json::array();
    for (int b = 0; b < u.correlation.cols(); ++b) row.push_back(number_or_null(u.correlation(a, b)));
    corr.push_back(row);
  }
  j["correlation"] = {{"names", names}, {"matrix", corr}};
  j["uncertainty"] = {{"residuals", u.m}, {"parameters", u.p}, {"dof", u.dof}, {"sse", u.sse},
                      {"sigma2", number_or_null(u.sigma2)}, {"t_quantile_975", number_or_null(u.t_quantile)},
                      {"singular_values_scaled", u.singular_values}, {"condition_number", number_or_null(u.condition_number)}};
  json warnings = fp.notes;
  for (const auto& w : u.warnings) warnings.push_back(w);
  j["warnings"] = warnings;
  j["conflicts"] = r.conflicts;
  json pe = json::array();
  for (const auto& a : r.per_experiment) {
    json alone = json::object();
    for (int k = 0; k < ps.num_free() && k < static_cast<int>(a.values.size()); ++k) {
      alone[ps.specs()[ps.free_indices()[k]].name] = {{"value", a.values[k]},
                                                       {"ci95", {number_or_null(a.ci95_lower[k]), number_or_null(a.ci95_upper[k])}},
                                                       {"identifiable", bool(a.identifiable[k])}};
    }
    pe.push_back({{"experiment", a.experiment}, {"usable", a.usable}, {"parameters", alone}});
  }
  j["per_experiment"] = pe;
  if (r.multistart.starts > 1) {
    const auto& ms = r.multistart;
    json sols = json::array();
    for (const auto& s : ms.solutions) sols.push_back({{"usable", s.usable}, {"cost", number_or_null(s.cost)}, {"start", s.start}, {"values", s.values}});
    json spread = json::object();
    for (int k = 0; k < ps.num_free() && k < static_cast<int>(ms.spread_min.size()); ++k) {
      spread[ps.specs()[ps.free_indices()[k]].name] = {{"min", ms.spread_min[k]}, {"max", ms.spread_max[k]}};
    }
    j["multistart"] = {{"starts", ms.starts}, {"best_start", ms.best_start}, {"starts_at_best_cost", ms.at_best},
                       {"spread_at_best_cost", spread}, {"solutions", sols}};
  }
  json ex = json::array();
  for (std::size_t i = 0; i < r.experiment_costs.size(); ++i) {
    const auto& e = r.experiment_costs[i];
    const auto c = fp.experiments[i]->axes();
    ex.push_back({{"name", e.name}, {"kind", e.kind}, {"points", e.points}, {"cost", e.cost}, {"rms", e.rms},
                  {"scale", fp.experiments[i]->scale()}, {"noise_given", fp.experiments[i]->noise_given()}, {"weight", fp.experiments[i]->weight()},
                  {"x", c.x_name}, {"y", c.y_name}, {"x_unit", c.x_unit}, {"y_unit", c.y_unit},
                  {"data_file", "experiments/" + e.name + ".csv"}});
  }
  j["experiments"] = ex;
  return j;
}

void write_fit_outputs(const FitProblem& fp, const FitResult& r, const io::OutputDirectory& out) {
  out.write_file("fit.json", fit_result_json(fp, r).dump(2) + "\n");
  out.write_file("card.toml", "# Fitted by spifit " SPIFIT_VERSION " from " + fp.file + "\n" + material::material_card_to_toml(r.card));
  std::filesystem::create_directories(out.path() / "experiments");
  const auto start = fp.parameters->apply(fp.parameters->initial_internal().data());
  for (const auto& e : fp.experiments) {
    const auto fin = e->compare(r.card.params);
    const auto ini = e->compare(start);
    const std::string x = fin.x_name.empty() ? "index" : fin.x_name;
    io::CsvTable t({x, "measured", "simulated_initial", "simulated_final"});
    for (std::size_t i = 0; i < fin.measured.size(); ++i) {
      const double nan = std::nan("");
      t.add_row({fin.x[i], fin.measured[i], ini.simulated.empty() ? nan : ini.simulated[i], fin.simulated.empty() ? nan : fin.simulated[i]});
    }
    out.write_file("experiments/" + e->name() + ".csv", t.str());
  }
}

std::string fit_table(const FitProblem& fp, const FitResult& r) {
  const auto& ps = *fp.parameters;
  const auto& u = r.uncertainty;
  std::string s;
  char line[256];
  std::snprintf(line, sizeof line, "fit %s: %s, %d iterations, %ld forward runs, %.3f s\n", fp.name.c_str(), r.algorithm.c_str(),
                r.iterations, r.forward_runs, r.wall_seconds);
  s += line;
  std::snprintf(line, sizeof line, "cost %.6g -> %.6g   (%s)\n", r.cost_initial, r.cost_final, r.termination.c_str());
  s += line;
  s += "parameter            initial          value        std.err          95 % interval\n";
  for (int k = 0; k < ps.num_free(); ++k) {
    const auto& name = ps.specs()[ps.free_indices()[k]].name;
    const double se = k < static_cast<int>(u.std_error.size()) ? u.std_error[k] : NAN;
    if (std::isfinite(se)) {
      std::snprintf(line, sizeof line, "%-14s %13.6g  %13.6g  %13.4g  [%.6g, %.6g]\n", name.c_str(), r.initial[k], r.values[k], se,
                    u.ci95_lower[k], u.ci95_upper[k]);
    } else {
      const bool ident = k < static_cast<int>(u.identifiable.size()) && u.identifiable[k];
      std::snprintf(line, sizeof line, "%-14s %13.6g  %13.6g  %13s  (%s)\n", name.c_str(), r.initial[k], r.values[k], "-",
                    ident ? "no degrees of freedom" : "NOT IDENTIFIABLE");
    }
    s += line;
  }
  for (const auto& e : r.experiment_costs) {
    std::snprintf(line, sizeof line, "  experiment %-22s %-6s %4d points  cost %.4g  rms %.4g\n", e.name.c_str(), e.kind.c_str(), e.points, e.cost, e.rms);
    s += line;
  }
  for (const auto& n : fp.notes) s += "NOTE: " + n + "\n";
  for (const auto& w : u.warnings) s += "WARNING: " + w + "\n";
  for (const auto& c : r.conflicts) s += "CONFLICT: " + c + "\n";
  if (r.multistart.starts > 1) {
    std::snprintf(line, sizeof line, "multi-start: %d of %d starts reached the best cost (seed in fit.json)\n", r.multistart.at_best, r.multistart.starts);
    s += line;
  }
  return s;
}

}  // namespace spifit::inverse
