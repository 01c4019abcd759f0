#include "inverse/fit/fit_output.hpp"

#include "forward/io/csv_writer.hpp"
#include "forward/io/host_and_time.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>

namespace spifit::inverse {

namespace {

// The name of free parameter k.
const std::string& free_name(const ParameterSet& ps, int k) { return ps.specs()[ps.free_indices()[k]].name; }

std::vector<FitRecord::Parameter> record_parameters(const ParameterSet& ps, const FitResult& r) {
  const auto& u = r.uncertainty;
  std::vector<FitRecord::Parameter> out;
  for (int k = 0; k < ps.num_free(); ++k) {
    const auto& s = ps.specs()[ps.free_indices()[k]];
    FitRecord::Parameter p;
    p.name = s.name;
    p.value = r.values[k];
    p.initial = r.initial[k];
    p.lower = s.lower;
    p.upper = s.upper;
    p.log_scale = s.log_scale;
    if (k < static_cast<int>(u.std_error.size())) {
      p.has_uncertainty = true;
      p.std_error = u.std_error[k];
      p.ci95_lower = u.ci95_lower[k];
      p.ci95_upper = u.ci95_upper[k];
      p.identifiable = u.identifiable[k];
    }
    out.push_back(p);
  }
  return out;
}

FitRecord::UncertaintySummary record_uncertainty(const Uncertainty& u) {
  FitRecord::UncertaintySummary s;
  s.residuals = u.m;
  s.parameters = u.p;
  s.dof = u.dof;
  s.sse = u.sse;
  s.sigma2 = u.sigma2;
  s.t_quantile_975 = u.t_quantile;
  s.singular_values_scaled = u.singular_values;
  s.condition_number = u.condition_number;
  s.relative_offset = u.relative_offset;
  return s;
}

std::vector<FitRecord::Alone> record_per_experiment(const ParameterSet& ps, const FitResult& r) {
  std::vector<FitRecord::Alone> out;
  for (const auto& a : r.per_experiment) {
    FitRecord::Alone alone;
    alone.experiment = a.experiment;
    alone.usable = a.usable;
    for (int k = 0; k < ps.num_free() && k < static_cast<int>(a.values.size()); ++k) {
      alone.parameters.push_back({free_name(ps, k), a.values[k], a.ci95_lower[k], a.ci95_upper[k], bool(a.identifiable[k])});
    }
    out.push_back(alone);
  }
  return out;
}

FitRecord::MultiStart record_multistart(const ParameterSet& ps, const FitResult::MultiStart& ms) {
  FitRecord::MultiStart out;
  out.starts = ms.starts;
  out.best_start = ms.best_start;
  out.starts_at_best_cost = ms.at_best;
  for (int k = 0; k < ps.num_free() && k < static_cast<int>(ms.spread_min.size()); ++k) {
    out.spread_at_best_cost.push_back({free_name(ps, k), ms.spread_min[k], ms.spread_max[k]});
  }
  for (const auto& s : ms.solutions) out.solutions.push_back({s.usable, s.cost, s.start, s.values});
  return out;
}

std::vector<FitRecord::Experiment> record_experiments(const FitProblem& fp, const FitResult& r) {
  std::vector<FitRecord::Experiment> out;
  for (std::size_t i = 0; i < r.experiment_costs.size(); ++i) {
    const auto& c = r.experiment_costs[i];
    const auto& e = *fp.experiments[i];
    const auto axes = e.axes();
    FitRecord::Experiment x;
    x.name = c.name;
    x.kind = c.kind;
    x.points = c.points;
    x.cost = c.cost;
    x.rms = c.rms;
    x.scale = e.scale();
    x.noise_given = e.noise_given();
    if (c.noise_points > 0) {
      x.noise_rms = c.noise_rms;
      x.noise_points = c.noise_points;
    }
    x.weight = e.weight();
    x.x = axes.x_name;
    x.y = axes.y_name;
    x.x_unit = axes.x_unit;
    x.y_unit = axes.y_unit;
    x.x_words = axes.x_words;
    x.y_words = axes.y_words;
    x.data_file = "experiments/" + c.name + ".csv";
    x.information_share = c.information_share;
    x.jacobian = e.jacobian();
    if (i < r.experiment_runs.size()) {
      const auto& runs = r.experiment_runs[i];
      x.evaluations = runs.evaluations;
      if (fp.scene_runs) {
        x.scene_runs = runs.scene_runs;
        x.run_seconds = runs.run_seconds;
      }
    }
    out.push_back(x);
  }
  return out;
}

}  // namespace

FitRecord fit_record(const FitProblem& fp, const FitResult& r) {
  const auto& ps = *fp.parameters;
  FitRecord rec;
  rec.spifit_version = SPIFIT_VERSION;
  rec.name = fp.name;
  rec.fit_file = fp.file;
  rec.algorithm = r.algorithm;
  rec.seed = r.seed;
  rec.termination = r.termination;
  rec.usable = r.usable;
  rec.not_usable = r.not_usable;
  rec.iterations = r.iterations;
  rec.forward_runs = r.forward_runs;
  if (fp.scene_runs) {
    rec.scene_runs = r.scene_runs;
    for (const auto& f : r.failed_runs) rec.failed_runs.push_back({f.scene, f.point, f.message, f.recovered});
    for (const auto& f : r.runs_by_scene) rec.runs_by_scene.push_back({f.scene, f.runs, f.failures, f.retried, f.seconds, f.median_seconds});
  }
  rec.wall_seconds = r.wall_seconds;
  rec.cost_definition = "1/2 sum of squared conditioned residuals sqrt(w) (simulated - measured) / scale";
  rec.cost_initial = r.cost_initial;
  rec.cost_final = r.cost_final;
  rec.cost_history = r.cost_history;
  rec.parameters = record_parameters(ps, r);
  for (const auto& s : ps.specs()) {
    if (s.fixed) rec.fixed.push_back({s.name, s.initial, ""});
  }
  if (ps.normalise_hill()) rec.fixed.push_back({"hill.H", FitRecord::kNaN, "2 - hill.G"});
  for (int k = 0; k < ps.num_free(); ++k) rec.correlation.names.push_back(free_name(ps, k));
  const auto& corr = r.uncertainty.correlation;
  for (int a = 0; a < corr.rows(); ++a) {
    rec.correlation.matrix.emplace_back();
    for (int b = 0; b < corr.cols(); ++b) rec.correlation.matrix.back().push_back(corr(a, b));
  }
  rec.uncertainty = record_uncertainty(r.uncertainty);
  rec.notes = fp.notes;
  rec.warnings = r.uncertainty.warnings;
  rec.conflicts = r.conflicts;
  rec.per_experiment = record_per_experiment(ps, r);
  if (r.multistart.starts > 1) rec.multistart = record_multistart(ps, r.multistart);
  rec.experiments = record_experiments(fp, r);
  return rec;
}

const char* fitted_file_suffix(bool usable) { return usable ? "" : "_NOT_USABLE"; }

std::string fit_date() {
  std::time_t t = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long s = std::strtoll(epoch, &end, 10);
    if (end != epoch && *end == '\0' && s >= 0) t = static_cast<std::time_t>(s);
  }
  return io::utc_iso(t).substr(0, 10);  // YYYY-MM-DD
}

material::MaterialCard fitted_card(const FitProblem& fp, const FitResult& r, const std::string& date) {
  material::MaterialCard card = r.card;
  const material::MaterialCard& start = fp.parameters->base();
  card.name = fp.name;
  card.description = std::string(r.usable ? "" : "NOT USABLE: ") + "fitted by spifit to the experiments of " + fp.file +
                     (fp.description.empty() ? "" : " (" + fp.description + ")");
  card.source = "spifit " SPIFIT_VERSION " fit " + fp.file + ", started from card " + start.name;
  card.file.clear();
  material::FitProvenance p;
  p.fit_file = fp.file;
  p.start_card = start.file.empty() ? start.name : start.file;
  p.data = fp.data_files;
  p.spifit_version = SPIFIT_VERSION;
  p.date = date;
  p.usable = r.usable;
  card.fitted = p;
  return card;
}

material::MaterialCard write_fit_outputs(const FitProblem& fp, const FitResult& r, const io::OutputDirectory& out) {
  out.write_file("fit.json", to_json(fit_record(fp, r)).dump(2) + "\n");
  const material::MaterialCard card = fitted_card(fp, r, fit_date());
  std::string head = "# Fitted by spifit " SPIFIT_VERSION " from " + fp.file + "\n";
  if (!r.usable) {
    head += "# NOT USABLE: this fit's result cannot be trusted:\n";
    for (const auto& why : r.not_usable) head += "#   - " + why + "\n";
  }
  out.write_file(std::string("card") + fitted_file_suffix(r.usable) + ".toml", head + material::material_card_to_toml(card));
  std::filesystem::create_directories(out.path() / "experiments");
  const ParameterPoint start = fp.parameters->point(fp.parameters->initial_internal().data());
  const ParameterPoint solution = fp.parameters->point_at(r.values);
  for (const auto& e : fp.experiments) {
    const auto fin = e->compare(solution);
    const auto ini = e->compare(start);
    const std::string x = fin.x_name.empty() ? "index" : fin.x_name;
    io::CsvTable t({x, "measured", "simulated_initial", "simulated_final"});
    for (std::size_t i = 0; i < fin.measured.size(); ++i) {
      const double nan = std::nan("");
      t.add_row({fin.x[i], fin.measured[i], ini.simulated.empty() ? nan : ini.simulated[i], fin.simulated.empty() ? nan : fin.simulated[i]});
    }
    out.write_file("experiments/" + e->name() + ".csv", t.str());
  }
  return card;
}

std::string fit_table(const FitProblem& fp, const FitResult& r) {
  const auto& ps = *fp.parameters;
  const auto& u = r.uncertainty;
  std::string s;
  char line[256];
  // With FE experiments the scene runs are what cost; their results answer the experiments'
  // further evaluations (the stopping rule's, the analysis at the solution) from the cache.
  if (fp.scene_runs)
    std::snprintf(line, sizeof line, "fit %s: %s, %d iterations, %ld FE scene runs (%ld evaluations of the experiments), %.3f s\n", fp.name.c_str(),
                  r.algorithm.c_str(), r.iterations, r.scene_runs, r.forward_runs, r.wall_seconds);
  else
    std::snprintf(line, sizeof line, "fit %s: %s, %d iterations, %ld forward runs, %.3f s\n", fp.name.c_str(), r.algorithm.c_str(), r.iterations,
                  r.forward_runs, r.wall_seconds);
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
  if (r.multistart.starts > 1) {
    std::snprintf(line, sizeof line, "multi-start: %d of %d starts reached the best cost (seed in fit.json)\n", r.multistart.at_best, r.multistart.starts);
    s += line;
  }
  return s;
}

}  // namespace spifit::inverse
