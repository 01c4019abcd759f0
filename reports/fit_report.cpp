#include "reports/fit_report.hpp"

#include "forward/io/atomic_file.hpp"

#include "forward/io/input_error.hpp"
#include "reports/plot.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace spifit::reports {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Thresholds of the verdicts (docs/reports.md).
constexpr double kCurveConflictRms = 2.0;    // curve, noise given: rms above this many sigma
constexpr double kScalarNoteSigma = 2.0;     // scalar, noise given: |residual| above this many sigma
constexpr double kScalarConflictSigma = 3.0;
constexpr double kOverfitRms = 0.5;          // curve, noise given: rms below this (>= 10 points)
constexpr double kRangeNote = 0.02;          // no noise given: rms as a fraction of the range / value
constexpr double kRangeConflict = 0.05;
constexpr double kRunsZ = -3.0;              // runs test of the residual signs
constexpr double kCorrNote = 0.95, kCorrWarn = 0.99;
constexpr double kRelErrNote = 0.5;          // std error / |value|
constexpr double kDominantShare = 0.5;

// Mean square of n independent standard-normal residuals: chi2(n)/n, mean 1, sd sqrt(2/n).
// Above 1 + 3 sd the residuals are significantly larger than the stated noise.
double chi2_bound(int n) { return 1.0 + 3.0 * std::sqrt(2.0 / n); }

// ---------------------------------------------------------------- formatting

std::string fmt(double v, int sig = 6) {
  if (!std::isfinite(v)) return "n/a";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", sig, v);
  return buf;
}
std::string fmt_fixed(double v, int dec) {
  if (!std::isfinite(v)) return "n/a";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", dec, v);
  if (std::string(buf) == "-0" || (std::string(buf).find_first_not_of("-0.") == std::string::npos && buf[0] == '-')) return buf + 1;
  return buf;
}
std::string fmt_pct(double fraction) {
  if (!std::isfinite(fraction)) return "n/a";
  if (fraction > 0 && fraction < 0.0005) return "< 0.1 %";
  return fmt_fixed(100.0 * fraction, 1) + " %";
}

// ---------------------------------------------------------------- the fit, read from disk

enum class Conditioning { noise, range, relative, unknown };

struct Param {
  std::string name;
  double value = kNaN, initial = kNaN, std_error = kNaN, ci_lo = kNaN, ci_hi = kNaN, lower = kNaN, upper = kNaN;
  bool has_uncertainty = false, identifiable = true, log_scale = false;
  std::string at_bound;  // "lower", "upper" or empty
};

struct Experiment {
  std::string name, kind, x, y, x_unit, y_unit, data_file;
  int points = 0;
  double cost = kNaN, rms = kNaN, scale = kNaN, weight = 1.0;
  int noise_given = -1;  // from fit.json when present (1/0), else -1: recognised from the data
  bool scalar = false;
  // experiments/NAME.csv
  bool have_csv = false;
  std::string x_column;
  std::vector<double> xs, measured, initial, final_;
  // derived
  Conditioning cond = Conditioning::unknown;
  double share_cost = kNaN, share_points = kNaN;
  int level = 0;  // 0 ok, 1 note, 2 conflict
  bool above_noise = false;  // rms significantly above 1 (noise given), below the conflict level
  std::string verdict;
  int sign_changes = -1;
  double expected_sign_changes = kNaN, runs_z = kNaN;
  std::string fit_plot, residual_plot;  // relative to DIR, when rendered
};

struct Fit {
  std::string file;  // DIR/fit.json as given
  std::string name, fit_file, algorithm, termination, version, cost_definition;
  bool has_usable = false, usable = true;
  double iterations = kNaN, forward_runs = kNaN, wall = kNaN, cost_initial = kNaN, cost_final = kNaN;
  std::vector<double> history;
  std::vector<Param> params;
  std::vector<std::pair<std::string, std::string>> fixed;
  std::vector<std::string> corr_names;
  std::vector<std::vector<double>> corr;
  double m = kNaN, p = kNaN, dof = kNaN, sse = kNaN, sigma2 = kNaN, t975 = kNaN, condition = kNaN;
  std::vector<double> singular_values;
  std::vector<std::string> warnings, conflicts;
  std::vector<Experiment> experiments;
  bool has_seed = false;
  double seed = kNaN;
  // per_experiment: each experiment fitted alone (fit file: per_experiment = true)
  struct Alone {
    std::string experiment;
    bool usable = true;
    struct Value {
      bool present = false, identifiable = true;
      double value = kNaN, lo = kNaN, hi = kNaN;
    };
    std::vector<Value> values;  // in the order of params
  };
  std::vector<Alone> alone;
  // multistart (fit file: multistart = N > 1)
  struct Multi {
    int starts = 0, best_start = -1, at_best = -1;
    std::vector<double> spread_min, spread_max;  // in the order of params (NaN: not given)
    struct Solution {
      bool usable = false;
      double cost = kNaN;
      std::vector<double> values;
    };
    std::vector<Solution> solutions;
  };
  bool has_multi = false;
  Multi multi;
};

// multistart is optional detail: read leniently, never fail the report on it.
void read_multistart(const json& m, Fit& fit) {
  if (!m.is_object()) return;
  auto integer = [&](const char* k) { return m.contains(k) && m[k].is_number() ? m[k].get<int>() : -1; };
  fit.multi.starts = integer("starts");
  fit.multi.best_start = integer("best_start");
  fit.multi.at_best = integer("starts_at_best_cost");
  if (fit.multi.starts <= 1) return;
  fit.has_multi = true;
  const json spread = m.contains("spread_at_best_cost") && m["spread_at_best_cost"].is_object() ? m["spread_at_best_cost"] : json::object();
  for (const auto& q : fit.params) {
    double lo = kNaN, hi = kNaN;
    if (spread.contains(q.name) && spread[q.name].is_object()) {
      const json& r = spread[q.name];
      if (r.contains("min") && r["min"].is_number()) lo = r["min"].get<double>();
      if (r.contains("max") && r["max"].is_number()) hi = r["max"].get<double>();
    }
    fit.multi.spread_min.push_back(lo);
    fit.multi.spread_max.push_back(hi);
  }
  if (m.contains("solutions") && m["solutions"].is_array()) {
    for (const auto& sj : m["solutions"]) {
      if (!sj.is_object()) continue;
      Fit::Multi::Solution so;
      so.usable = sj.contains("usable") && sj["usable"].is_boolean() && sj["usable"].get<bool>();
      if (sj.contains("cost") && sj["cost"].is_number()) so.cost = sj["cost"].get<double>();
      if (sj.contains("values") && sj["values"].is_array()) {
        for (const auto& v : sj["values"]) so.values.push_back(v.is_number() ? v.get<double>() : kNaN);
      }
      fit.multi.solutions.push_back(so);
    }
  }
}

[[noreturn]] void bad(const std::string& file, const std::string& key, const json& value, const std::string& what) {
  std::string v = value.is_null() ? std::string() : value.dump();
  if (v.size() > 60) v = v.substr(0, 57) + "...";
  throw io::InputError(file, key, v, what);
}

double num(const std::string& file, const json& obj, const std::string& key, const std::string& path) {
  if (!obj.is_object() || !obj.contains(key) || obj.at(key).is_null()) return kNaN;
  const json& v = obj.at(key);
  if (!v.is_number()) bad(file, path + key, v, "expected a number");
  return v.get<double>();
}
std::string str(const std::string& file, const json& obj, const std::string& key, const std::string& path) {
  if (!obj.is_object() || !obj.contains(key) || obj.at(key).is_null()) return {};
  const json& v = obj.at(key);
  if (!v.is_string()) bad(file, path + key, v, "expected a string");
  return v.get<std::string>();
}
std::vector<double> numbers(const std::string& file, const json& obj, const std::string& key, const std::string& path) {
  std::vector<double> out;
  if (!obj.is_object() || !obj.contains(key) || obj.at(key).is_null()) return out;
  const json& v = obj.at(key);
  if (!v.is_array()) bad(file, path + key, v, "expected an array of numbers");
  for (const auto& e : v) {
    if (e.is_null()) out.push_back(kNaN);
    else if (e.is_number()) out.push_back(e.get<double>());
    else bad(file, path + key, e, "expected an array of numbers");
  }
  return out;
}

// A path inside DIR (relative, no ".."), else empty.
fs::path inside(const std::string& rel) {
  if (rel.empty()) return {};
  const fs::path p = fs::path(rel).lexically_normal();
  if (p.is_absolute() || p.empty() || *p.begin() == "..") return {};
  return p;
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') out.emplace_back();
    else if (c != '\r') out.back() += c;
  }
  return out;
}

// Reads DIR/experiments/NAME.csv: columns X (or "index"), measured, simulated_initial, simulated_final.
bool read_experiment_csv(const fs::path& path, Experiment& e, std::string& why) {
  std::ifstream f(path);
  if (!f) {
    why = "cannot read " + path.string();
    return false;
  }
  std::string line;
  if (!std::getline(f, line)) {
    why = path.string() + " is empty";
    return false;
  }
  const auto header = split_csv_line(line);
  int im = -1, ii = -1, ifi = -1;
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (header[k] == "measured") im = static_cast<int>(k);
    if (header[k] == "simulated_initial") ii = static_cast<int>(k);
    if (header[k] == "simulated_final") ifi = static_cast<int>(k);
  }
  if (im <= 0 || ifi <= 0) {
    why = path.string() + ": expected the columns X, measured, simulated_initial, simulated_final";
    return false;
  }
  e.x_column = header[0];
  int row = 1;
  while (std::getline(f, line)) {
    ++row;
    if (line.empty() || line == "\r") continue;
    const auto cells = split_csv_line(line);
    if (cells.size() != header.size()) {
      why = path.string() + ": row " + std::to_string(row) + " has " + std::to_string(cells.size()) + " cells, the header " +
            std::to_string(header.size());
      return false;
    }
    auto value = [&](int k) {
      if (k < 0) return kNaN;
      const std::string& s = cells[static_cast<std::size_t>(k)];
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);
      return (end == s.c_str() || *end != '\0') ? kNaN : v;
    };
    e.xs.push_back(value(0));
    e.measured.push_back(value(im));
    e.initial.push_back(value(ii));
    e.final_.push_back(value(ifi));
  }
  if (e.measured.empty()) {
    why = path.string() + " has no data rows";
    return false;
  }
  e.have_csv = true;
  return true;
}

Fit load_fit(const fs::path& dir) {
  Fit fit;
  const fs::path path = dir / "fit.json";
  fit.file = path.string();
  const std::string& file = fit.file;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw io::InputError(file, "", "", fs::exists(dir, ec) ? "no fit.json here: not an output directory of `spifit fit`"
                                                           : "no such directory");
  }
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
  if (!j.is_object()) throw io::InputError(file, "", "", "not a fit.json: the top level is not an object");
  try {
    if (!j.contains("parameters") || !j["parameters"].is_object()) bad(file, "parameters", j.value("parameters", json()), "missing or not an object: not a fit.json");
    if (!j.contains("experiments") || !j["experiments"].is_array()) bad(file, "experiments", j.value("experiments", json()), "missing or not an array: not a fit.json");
    fit.name = str(file, j, "fit", "");
    fit.fit_file = str(file, j, "fit_file", "");
    fit.algorithm = str(file, j, "algorithm", "");
    fit.termination = str(file, j, "termination", "");
    fit.version = str(file, j, "spifit_version", "");
    fit.cost_definition = str(file, j, "cost_definition", "");
    if (j.contains("usable") && j["usable"].is_boolean()) {
      fit.has_usable = true;
      fit.usable = j["usable"].get<bool>();
    }
    fit.iterations = num(file, j, "iterations", "");
    fit.forward_runs = num(file, j, "forward_runs", "");
    fit.wall = num(file, j, "wall_seconds", "");
    fit.cost_initial = num(file, j, "cost_initial", "");
    fit.cost_final = num(file, j, "cost_final", "");
    fit.history = numbers(file, j, "cost_history", "");

    // Parameters in the order of the fit (correlation.names), others after them.
    std::vector<std::string> order;
    if (j.contains("correlation") && j["correlation"].is_object()) {
      const json& c = j["correlation"];
      if (c.contains("names") && c["names"].is_array()) {
        for (const auto& n : c["names"]) {
          if (!n.is_string()) bad(file, "correlation.names", n, "expected strings");
          fit.corr_names.push_back(n.get<std::string>());
        }
      }
      if (c.contains("matrix") && c["matrix"].is_array()) {
        for (const auto& row : c["matrix"]) {
          if (!row.is_array()) bad(file, "correlation.matrix", row, "expected an array of rows");
          std::vector<double> r;
          for (const auto& v : row) r.push_back(v.is_number() ? v.get<double>() : kNaN);
          fit.corr.push_back(r);
        }
      }
    }
    for (const auto& n : fit.corr_names) {
      if (j["parameters"].contains(n)) order.push_back(n);
    }
    for (const auto& [n, v] : j["parameters"].items()) {
      if (std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
    }
    for (const auto& n : order) {
      const json& pj = j["parameters"][n];
      const std::string at = "parameters." + n + ".";
      if (!pj.is_object()) bad(file, "parameters." + n, pj, "expected an object");
      Param p;
      p.name = n;
      p.value = num(file, pj, "value", at);
      p.initial = num(file, pj, "initial", at);
      p.lower = num(file, pj, "lower", at);
      p.upper = num(file, pj, "upper", at);
      p.log_scale = pj.contains("log_scale") && pj["log_scale"].is_boolean() && pj["log_scale"].get<bool>();
      if (pj.contains("std_error") || pj.contains("identifiable")) {
        p.has_uncertainty = true;
        p.std_error = num(file, pj, "std_error", at);
        const auto ci = numbers(file, pj, "ci95", at);
        if (ci.size() == 2) {
          p.ci_lo = ci[0];
          p.ci_hi = ci[1];
        }
        p.identifiable = !(pj.contains("identifiable") && pj["identifiable"].is_boolean() && !pj["identifiable"].get<bool>());
      }
      fit.params.push_back(p);
    }
    if (j.contains("fixed") && j["fixed"].is_object()) {
      for (const auto& [n, v] : j["fixed"].items()) {
        fit.fixed.emplace_back(n, v.is_string() ? v.get<std::string>() : v.is_number() ? fmt(v.get<double>(), 10) : v.dump());
      }
    }
    if (j.contains("uncertainty") && j["uncertainty"].is_object()) {
      const json& u = j["uncertainty"];
      const std::string at = "uncertainty.";
      fit.m = num(file, u, "residuals", at);
      fit.p = num(file, u, "parameters", at);
      fit.dof = num(file, u, "dof", at);
      fit.sse = num(file, u, "sse", at);
      fit.sigma2 = num(file, u, "sigma2", at);
      fit.t975 = num(file, u, "t_quantile_975", at);
      fit.condition = num(file, u, "condition_number", at);
      fit.singular_values = numbers(file, u, "singular_values_scaled", at);
    }
    for (const char* key : {"warnings", "conflicts"}) {
      if (!j.contains(key) || j[key].is_null()) continue;
      if (!j[key].is_array()) bad(file, key, j[key], "expected an array of strings");
      auto& into = std::string(key) == "warnings" ? fit.warnings : fit.conflicts;
      for (const auto& w : j[key]) into.push_back(w.is_string() ? w.get<std::string>() : w.dump());
    }
    if (j.contains("seed") && j["seed"].is_number()) {
      fit.has_seed = true;
      fit.seed = j["seed"].get<double>();
    }
    if (j.contains("per_experiment") && j["per_experiment"].is_array()) {
      int a = 0;
      for (const auto& pe : j["per_experiment"]) {
        const std::string at = "per_experiment[" + std::to_string(a++) + "].";
        if (!pe.is_object()) bad(file, at.substr(0, at.size() - 1), pe, "expected an object");
        Fit::Alone al;
        al.experiment = str(file, pe, "experiment", at);
        al.usable = !(pe.contains("usable") && pe["usable"].is_boolean() && !pe["usable"].get<bool>());
        const json params = pe.contains("parameters") && pe["parameters"].is_object() ? pe["parameters"] : json::object();
        for (const auto& q : fit.params) {
          Fit::Alone::Value v;
          if (params.contains(q.name) && params[q.name].is_object()) {
            const json& pj = params[q.name];
            const std::string pat = at + "parameters." + q.name + ".";
            v.present = true;
            v.value = num(file, pj, "value", pat);
            const auto ci = numbers(file, pj, "ci95", pat);
            if (ci.size() == 2) {
              v.lo = ci[0];
              v.hi = ci[1];
            }
            v.identifiable = !(pj.contains("identifiable") && pj["identifiable"].is_boolean() && !pj["identifiable"].get<bool>());
          }
          al.values.push_back(v);
        }
        fit.alone.push_back(al);
      }
    }
    if (j.contains("multistart")) read_multistart(j["multistart"], fit);
    int k = 0;
    for (const auto& ej : j["experiments"]) {
      const std::string at = "experiments[" + std::to_string(k++) + "].";
      if (!ej.is_object()) bad(file, at.substr(0, at.size() - 1), ej, "expected an object");
      Experiment e;
      e.name = str(file, ej, "name", at);
      if (e.name.empty()) bad(file, at + "name", json(), "missing experiment name");
      e.kind = str(file, ej, "kind", at);
      e.scalar = e.kind == "scalar";
      e.x = str(file, ej, "x", at);
      e.y = str(file, ej, "y", at);
      e.x_unit = str(file, ej, "x_unit", at);
      e.y_unit = str(file, ej, "y_unit", at);
      e.data_file = str(file, ej, "data_file", at);
      const double pts = num(file, ej, "points", at);
      e.points = std::isfinite(pts) ? static_cast<int>(pts) : 0;
      e.cost = num(file, ej, "cost", at);
      e.rms = num(file, ej, "rms", at);
      e.scale = num(file, ej, "scale", at);
      const double w = num(file, ej, "weight", at);
      e.weight = std::isfinite(w) ? w : 1.0;
      if (ej.contains("noise_given") && ej["noise_given"].is_boolean()) e.noise_given = ej["noise_given"].get<bool>() ? 1 : 0;
      fit.experiments.push_back(std::move(e));
    }
  } catch (const json::exception& e) {
    throw io::InputError(file, "", "", std::string("unexpected content: ") + e.what());
  }
  return fit;
}

// ---------------------------------------------------------------- analysis

struct Finding {
  int level = 2;  // 2 warning, 1 note
  std::string text;
};

std::string sigma_unit(const Experiment& e) {
  switch (e.cond) {
    case Conditioning::noise: return "σ";
    default: return "× scale";
  }
}

std::string with_unit(const std::string& v, const std::string& unit) {
  return (unit.empty() || unit == "-") ? v : v + " " + unit;
}

void analyse_experiment(Experiment& e) {
  // Which divisor conditioned the residuals: the stated noise, or (none given) the range of the
  // measured curve / the magnitude of the measured value. fit.json says so (noise_given); older
  // files keep only the divisor, which is then recognised from the data.
  if (e.noise_given == 1) {
    e.cond = Conditioning::noise;
  } else if (e.noise_given == 0) {
    e.cond = e.scalar ? Conditioning::relative : Conditioning::range;
  } else if (e.have_csv && std::isfinite(e.scale) && e.scale > 0) {
    const auto tol = [&](double a) { return std::abs(e.scale - a) <= 1e-9 * std::max(std::abs(a), 1e-300); };
    if (e.scalar) {
      e.cond = tol(std::abs(e.measured[0])) ? Conditioning::relative : Conditioning::noise;
    } else {
      double lo = INFINITY, hi = -INFINITY;
      for (double v : e.measured) {
        if (std::isfinite(v)) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
      }
      e.cond = (hi > lo && tol(hi - lo)) ? Conditioning::range : Conditioning::noise;
    }
  }
  // Runs test on the signs of the final residuals: independent noise changes sign about every
  // other point; a curve the model cannot follow gives long runs of one sign.
  if (!e.scalar && e.have_csv) {
    std::vector<int> signs;
    for (std::size_t i = 0; i < e.measured.size(); ++i) {
      const double r = e.final_[i] - e.measured[i];
      if (std::isfinite(r) && r != 0.0) signs.push_back(r > 0 ? 1 : -1);
    }
    const double n = static_cast<double>(signs.size());
    if (n >= 10) {
      double n1 = 0;
      int changes = 0;
      for (std::size_t i = 0; i < signs.size(); ++i) {
        if (signs[i] > 0) ++n1;
        if (i && signs[i] != signs[i - 1]) ++changes;
      }
      const double n2 = n - n1;
      e.sign_changes = changes;
      e.expected_sign_changes = 2.0 * n1 * n2 / n;  // expected runs - 1
      const double var = 2.0 * n1 * n2 * (2.0 * n1 * n2 - n) / (n * n * (n - 1.0));
      if (var > 0) e.runs_z = (changes - e.expected_sign_changes) / std::sqrt(var);
    }
  }
  const double r = e.rms;
  char buf[320];
  if (!std::isfinite(r)) {
    e.level = 2;
    e.verdict = "no residual (the forward run failed?)";
    return;
  }
  switch (e.cond) {
    case Conditioning::noise:
    case Conditioning::unknown: {
      const std::string u = e.cond == Conditioning::noise ? "σ" : "× scale";
      if (e.scalar) {
        if (r > kScalarConflictSigma) {
          e.level = 2;
          std::snprintf(buf, sizeof buf, "CONFLICT: off by %.1f %s", r, u.c_str());
        } else if (r > kScalarNoteSigma) {
          e.level = 1;
          std::snprintf(buf, sizeof buf, "off by %.1f %s", r, u.c_str());
        } else {
          std::snprintf(buf, sizeof buf, "within %.2f %s", r, u.c_str());
        }
      } else if (r > kCurveConflictRms) {
        e.level = 2;
        std::snprintf(buf, sizeof buf, "CONFLICT: rms %.2f %s", r, u.c_str());
      } else if (e.points >= 10 && e.cond == Conditioning::noise && r * r > chi2_bound(e.points)) {
        e.level = 1;
        e.above_noise = true;
        std::snprintf(buf, sizeof buf, "rms %.2f σ: larger than the noise", r);
      } else if (r < kOverfitRms && e.points >= 10 && e.cond == Conditioning::noise) {
        e.level = 1;
        std::snprintf(buf, sizeof buf, "rms %.2f σ: below the stated noise", r);
      } else {
        std::snprintf(buf, sizeof buf, "%s (rms %.2f %s)", e.cond == Conditioning::noise ? "consistent with the noise" : "ok", r, u.c_str());
      }
      break;
    }
    case Conditioning::range:
    case Conditioning::relative: {
      const char* of = e.cond == Conditioning::range ? "of the data range" : "of the value";
      e.level = r > kRangeConflict ? 2 : r > kRangeNote ? 1 : 0;
      std::snprintf(buf, sizeof buf, "%s%.2f %% %s", e.level == 2 ? "POOR: rms " : "rms ", 100.0 * r, of);
      break;
    }
  }
  e.verdict = buf;
}

bool near(double a, double b, double span) { return std::abs(a - b) <= 1e-6 * span; }

std::vector<Finding> analyse(Fit& fit) {
  std::vector<Finding> out;
  char buf[640];
  if (fit.has_usable && !fit.usable) {
    out.push_back({2, "The fit FAILED and its result is not usable (" + fit.termination + "). Do not use card.toml."});
  } else if (fit.termination.rfind("NO_CONVERGENCE", 0) == 0 || fit.termination.rfind("FAILURE", 0) == 0) {
    out.push_back({2, "The optimiser stopped without converging (" + fit.termination + "): the values may not be the best fit."});
  }
  for (const auto& w : fit.warnings) out.push_back({2, w});
  for (const auto& c : fit.conflicts) {
    out.push_back({2, "Conflict: " + c});
  }

  double total = 0.0;
  long total_points = 0;
  for (const auto& e : fit.experiments) {
    if (std::isfinite(e.cost)) total += e.cost;
    total_points += e.points;
  }
  for (auto& e : fit.experiments) {
    e.share_cost = total > 0 ? e.cost / total : kNaN;
    e.share_points = total_points > 0 ? static_cast<double>(e.points) / static_cast<double>(total_points) : kNaN;
    analyse_experiment(e);
    const std::string yname = e.y.empty() ? "the observable" : e.y;
    if (e.level == 2 && std::isfinite(e.rms)) {
      if (e.cond == Conditioning::range || e.cond == Conditioning::relative) {
        std::snprintf(buf, sizeof buf,
                      "Experiment %s is fitted poorly: its rms residual is %.1f %% %s. No noise was given, so this cannot be "
                      "judged statistically, but the model does not follow these data.",
                      e.name.c_str(), 100.0 * e.rms, e.cond == Conditioning::range ? "of the measured range" : "of the measured value");
      } else if (e.scalar) {
        std::snprintf(buf, sizeof buf,
                      "Experiment %s disagrees with the model: the fitted %s is %.1f %s away from the measured value. The data "
                      "conflict with the model or with the other experiments (or the stated noise is too small).",
                      e.name.c_str(), yname.c_str(), e.rms, sigma_unit(e).c_str());
      } else {
        std::snprintf(buf, sizeof buf,
                      "Experiment %s disagrees with the model: its residuals are %.1f times the stated noise (rms %.2f; about 1 is "
                      "expected). The data conflict with the model or with the other experiments (or the stated noise is too "
                      "small); it carries %s of the total cost.",
                      e.name.c_str(), e.rms, e.rms, fmt_pct(e.share_cost).c_str());
      }
      out.push_back({2, buf});
    } else if (e.level == 1 && e.scalar) {
      std::snprintf(buf, sizeof buf, "Experiment %s: the fitted %s is %.1f %s from the measured value.", e.name.c_str(), yname.c_str(),
                    e.rms, sigma_unit(e).c_str());
      out.push_back({1, buf});
    } else if (e.level == 1 && e.above_noise) {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s: residuals (rms %.2f σ) are significantly larger than the stated noise (random noise over "
                    "%d points stays below about %.2f σ): a mild disagreement with the model or the other experiments, or the "
                    "noise is understated.",
                    e.name.c_str(), e.rms, e.points, std::sqrt(chi2_bound(e.points)));
      out.push_back({1, buf});
    } else if (e.level == 1 && e.cond == Conditioning::noise) {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s: residuals (rms %.2f σ) are clearly smaller than the stated noise; the noise may be overstated, "
                    "which widens the confidence intervals.",
                    e.name.c_str(), e.rms);
      out.push_back({1, buf});
    } else if (e.level == 1) {
      std::snprintf(buf, sizeof buf, "Experiment %s: rms residual %.1f %% %s.", e.name.c_str(), 100.0 * e.rms,
                    e.cond == Conditioning::range ? "of the measured range" : "of the measured value");
      out.push_back({1, buf});
    }
    if (std::isfinite(e.runs_z) && e.runs_z < kRunsZ) {
      std::snprintf(buf, sizeof buf,
                    "Experiment %s: the residual changes sign only %d times in %d points (about %.0f expected for independent "
                    "noise): the deviation is systematic - the model's curve shape differs from the data, or the measurement "
                    "noise is correlated.",
                    e.name.c_str(), e.sign_changes, static_cast<int>(e.measured.size()), e.expected_sign_changes);
      out.push_back({1, buf});
    }
    if (fit.experiments.size() >= 3 && std::isfinite(e.share_cost) && e.share_cost > kDominantShare) {
      std::snprintf(buf, sizeof buf, "Experiment %s carries %s of the total cost (%s of the points): it dominates the fit.", e.name.c_str(),
                    fmt_pct(e.share_cost).c_str(), fmt_pct(e.share_points).c_str());
      out.push_back({1, buf});
    }
  }

  for (auto& p : fit.params) {
    if (!std::isfinite(p.value) || !std::isfinite(p.lower) || !std::isfinite(p.upper) || !(p.upper > p.lower)) continue;
    const bool logs = p.log_scale && p.lower > 0 && p.value > 0;
    const double span = logs ? std::log(p.upper / p.lower) : p.upper - p.lower;
    const double v = logs ? std::log(p.value) : p.value;
    if (near(v, logs ? std::log(p.lower) : p.lower, span)) p.at_bound = "lower";
    if (near(v, logs ? std::log(p.upper) : p.upper, span)) p.at_bound = "upper";
    bool told = false;  // fit.json already warns about this bound
    for (const auto& w : fit.warnings) told = told || (w.rfind(p.name + " ", 0) == 0 && w.find("bound") != std::string::npos);
    if (!p.at_bound.empty() && !told) {
      out.push_back({2, p.name + " sits at its " + p.at_bound + " bound (" + fmt(p.at_bound == "lower" ? p.lower : p.upper) +
                            "): the data push it beyond the allowed range, so the bound, not the data, sets its value and its "
                            "uncertainty is not meaningful. Check the bounds, or the data that drive it."});
    }
    if (p.has_uncertainty && p.identifiable && std::isfinite(p.std_error) && p.value != 0 &&
        p.std_error / std::abs(p.value) > kRelErrNote) {
      out.push_back({1, p.name + " is poorly determined: its standard error is " + fmt_pct(p.std_error / std::abs(p.value)) +
                            " of its value."});
    }
  }

  if (fit.has_multi) {
    const auto& m = fit.multi;
    for (std::size_t k = 0; k < fit.params.size() && k < m.spread_min.size(); ++k) {
      const auto& q = fit.params[k];
      const double lo = m.spread_min[k], hi = m.spread_max[k];
      if (!std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(q.value)) continue;
      const double tol = std::max(1e-3 * std::abs(q.value), std::isfinite(q.std_error) ? q.std_error : 0.0);
      if (hi - lo > tol) {
        out.push_back({1, "Starts that reached the same best cost give " + q.name + " from " + fmt(lo) + " to " + fmt(hi) +
                              ": the data do not determine it uniquely."});
      }
    }
  }

  const std::size_t n = fit.corr.size();
  for (std::size_t a = 0; a < n && a < fit.corr_names.size(); ++a) {
    for (std::size_t b = a + 1; b < fit.corr[a].size() && b < fit.corr_names.size(); ++b) {
      const double r = fit.corr[a][b];
      if (!std::isfinite(r) || std::abs(r) < kCorrNote) continue;
      std::snprintf(buf, sizeof buf,
                    "%s and %s are %s correlated (r = %.3f): the data determine a combination of the two much better than "
                    "each one.",
                    fit.corr_names[a].c_str(), fit.corr_names[b].c_str(), std::abs(r) >= kCorrWarn ? "almost perfectly" : "strongly", r);
      out.push_back({std::abs(r) >= kCorrWarn ? 2 : 1, buf});
    }
  }
  return out;
}

// ---------------------------------------------------------------- document model

struct Span {
  std::string text;
  bool bold = false, code = false;
  std::string href;
  Span(std::string t) : text(std::move(t)) {}  // NOLINT: implicit, plain text
  Span(std::string t, bool b, bool c, std::string h = {}) : text(std::move(t)), bold(b), code(c), href(std::move(h)) {}
};
using Inline = std::vector<Span>;

struct Cell {
  std::string text;
  std::string cls;       // "bad", "warn", "good", "diag" or empty
  double shade = kNaN;   // correlation colouring in HTML, -1..1
};

struct Table {
  std::string id;
  std::vector<std::string> header;
  std::vector<bool> right;  // right-aligned (numeric) columns
  std::vector<std::vector<Cell>> rows;
};

struct Block {
  enum class Kind { heading, paragraph, table, callout, list, figure };
  explicit Block(Kind k) : kind(k) {}
  Kind kind;
  int level = 2;
  std::string anchor;
  Inline text;
  Table table;
  std::string cls;  // callout: "warn", "note", "ok"
  std::string title;
  std::vector<Inline> items;
  std::string src, alt;
};

struct Doc {
  std::string title;
  std::vector<Block> blocks;
  void heading(int level, const std::string& t, const std::string& anchor = "") {
    Block b{Block::Kind::heading};
    b.level = level;
    b.text = {{t}};
    b.anchor = anchor;
    blocks.push_back(b);
  }
  void para(Inline t) {
    Block b{Block::Kind::paragraph};
    b.text = std::move(t);
    blocks.push_back(b);
  }
  void table(Table t) {
    Block b{Block::Kind::table};
    b.table = std::move(t);
    blocks.push_back(b);
  }
  void callout(const std::string& cls, const std::string& heading_text, std::vector<Inline> items) {
    Block b{Block::Kind::callout};
    b.cls = cls;
    b.title = heading_text;
    b.items = std::move(items);
    blocks.push_back(b);
  }
  void list(std::vector<Inline> items) {
    Block b{Block::Kind::list};
    b.items = std::move(items);
    blocks.push_back(b);
  }
  void figure(const std::string& src, const std::string& alt) {
    Block b{Block::Kind::figure};
    b.src = src;
    b.alt = alt;
    blocks.push_back(b);
  }
};

// ---------------------------------------------------------------- Markdown

std::string md_escape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const char next = i + 1 < s.size() ? s[i + 1] : '\0';
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '|': out += "\\|"; break;
      case '*': out += "\\*"; break;
      case '`': out += "\\`"; break;
      case ']': out += next == '(' ? "\\]" : "]"; break;  // "[a](b)" would become a link
      case '<': out += (std::isalpha(static_cast<unsigned char>(next)) || next == '/' || next == '!' || next == '?') ? "&lt;" : "<"; break;
      case '\n': case '\r': case '\t': out += ' '; break;
      default: out += c;
    }
  }
  return out;
}

std::string md_inline(const Inline& spans) {
  std::string out;
  for (const auto& s : spans) {
    std::string t;
    if (s.code) {
      std::string c = s.text;
      for (auto& ch : c) {
        if (ch == '`' || ch == '\n' || ch == '\r') ch = '\'';
      }
      t = "`" + c + "`";
    } else {
      t = md_escape(s.text);
    }
    if (!s.href.empty()) t = "[" + t + "](" + s.href + ")";
    if (s.bold) t = "**" + t + "**";
    out += t;
  }
  return out;
}

std::string to_markdown(const Doc& doc) {
  std::string md = "# " + md_escape(doc.title) + "\n";
  for (const auto& b : doc.blocks) {
    md += "\n";
    switch (b.kind) {
      case Block::Kind::heading: md += std::string(static_cast<std::size_t>(b.level), '#') + " " + md_inline(b.text) + "\n"; break;
      case Block::Kind::paragraph: md += md_inline(b.text) + "\n"; break;
      case Block::Kind::callout: {
        md += "> **" + md_escape(b.title) + "**\n>\n";
        for (const auto& it : b.items) md += "> - " + md_inline(it) + "\n";
        break;
      }
      case Block::Kind::list:
        for (const auto& it : b.items) md += "- " + md_inline(it) + "\n";
        break;
      case Block::Kind::figure: md += "![" + md_escape(b.alt) + "](" + b.src + ")\n"; break;
      case Block::Kind::table: {
        const Table& t = b.table;
        md += "|";
        for (const auto& h : t.header) {
          md += ' ';
          md += md_escape(h);
          md += " |";
        }
        md += "\n|";
        for (std::size_t k = 0; k < t.header.size(); ++k) md += (k < t.right.size() && t.right[k]) ? "---:|" : "---|";
        md += "\n";
        for (const auto& row : t.rows) {
          md += "|";
          for (const auto& c : row) {
            const std::string text = md_escape(c.text);
            std::string shown = text;
            if (!text.empty() && c.cls == "bad") shown = "**" + text + "**";
            if (!text.empty() && c.cls == "warn") shown = "*" + text + "*";
            md += " " + shown + " |";
          }
          md += "\n";
        }
        break;
      }
    }
  }
  return md;
}

// ---------------------------------------------------------------- HTML

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string html_inline(const Inline& spans) {
  std::string out;
  for (const auto& s : spans) {
    std::string t = html_escape(s.text);
    if (s.code) t = "<code>" + t + "</code>";
    if (!s.href.empty()) t = "<a href=\"" + html_escape(s.href) + "\">" + t + "</a>";
    if (s.bold) t = "<strong>" + t + "</strong>";
    out += t;
  }
  return out;
}

const char* kCss = R"(body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,Helvetica,Arial,sans-serif;max-width:1100px;margin:2em auto;padding:0 1.2em;color:#222;line-height:1.45}
h1{border-bottom:2px solid #444;padding-bottom:.2em}h2{margin-top:1.8em;border-bottom:1px solid #ccc;padding-bottom:.15em}
table{border-collapse:collapse;margin:.8em 0;font-size:.92em}th,td{border:1px solid #ccc;padding:.3em .6em;vertical-align:top}
th{background:#f0f0f0;text-align:left}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
td.bad{background:#fdecea;color:#a50e0e;font-weight:bold}td.warn{background:#fff8e1}td.good{color:#1b5e20}td.diag{background:#eee;color:#777}
.callout{border-left:6px solid;padding:.5em 1em;margin:1em 0;border-radius:3px}.callout p{margin:.2em 0;font-weight:bold}
.callout ul{margin:.3em 0 .2em 1.2em;padding:0}.callout.warn{border-color:#c62828;background:#fdecea}.callout.note{border-color:#f9a825;background:#fffde7}
.callout.ok{border-color:#2e7d32;background:#e8f5e9}figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}
figcaption{font-size:.85em;color:#555}code{background:#f4f4f4;padding:0 .2em;border-radius:2px})";

std::string to_html(const Doc& doc) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escape(doc.title) +
                  "</title>\n<style>\n" + kCss + "\n</style>\n</head>\n<body>\n<h1>" + html_escape(doc.title) + "</h1>\n";
  for (const auto& b : doc.blocks) {
    switch (b.kind) {
      case Block::Kind::heading: {
        const std::string tag = "h" + std::to_string(b.level);
        h += "<" + tag + (b.anchor.empty() ? std::string() : " id=\"" + html_escape(b.anchor) + "\"") + ">" + html_inline(b.text) + "</" + tag + ">\n";
        break;
      }
      case Block::Kind::paragraph: h += "<p>" + html_inline(b.text) + "</p>\n"; break;
      case Block::Kind::callout: {
        h += "<div class=\"callout " + html_escape(b.cls) + "\">\n<p>" + html_escape(b.title) + "</p>\n<ul>\n";
        for (const auto& it : b.items) h += "<li>" + html_inline(it) + "</li>\n";
        h += "</ul>\n</div>\n";
        break;
      }
      case Block::Kind::list: {
        h += "<ul>\n";
        for (const auto& it : b.items) h += "<li>" + html_inline(it) + "</li>\n";
        h += "</ul>\n";
        break;
      }
      case Block::Kind::figure:
        h += "<figure>\n<img src=\"" + html_escape(b.src) + "\" alt=\"" + html_escape(b.alt) + "\">\n<figcaption>" + html_escape(b.alt) +
             "</figcaption>\n</figure>\n";
        break;
      case Block::Kind::table: {
        const Table& t = b.table;
        h += "<table" + (t.id.empty() ? std::string() : " id=\"" + html_escape(t.id) + "\"") + ">\n<thead>\n<tr>";
        for (const auto& c : t.header) h += "<th>" + html_escape(c) + "</th>";
        h += "</tr>\n</thead>\n<tbody>\n";
        for (const auto& row : t.rows) {
          h += "<tr>";
          for (std::size_t k = 0; k < row.size(); ++k) {
            const Cell& c = row[k];
            std::string cls = (k < t.right.size() && t.right[k]) ? "num" : "";
            if (!c.cls.empty()) cls += (cls.empty() ? "" : " ") + c.cls;
            std::string style;
            if (std::isfinite(c.shade) && c.cls.empty()) {
              char buf[96];
              const double a = std::min(1.0, std::abs(c.shade)) * 0.75;
              std::snprintf(buf, sizeof buf, " style=\"background:rgba(%s,%.2f)\"", c.shade >= 0 ? "31,119,180" : "214,39,40", a);
              style = buf;
            }
            h += "<td" + (cls.empty() ? std::string() : " class=\"" + cls + "\"") + style + ">" + html_escape(c.text) + "</td>";
          }
          h += "</tr>\n";
        }
        h += "</tbody>\n</table>\n";
        break;
      }
    }
  }
  h += "</body>\n</html>\n";
  return h;
}

// ---------------------------------------------------------------- plots

struct PlotRun {
  fs::path gnuplot;
  fs::path plots_dir;
  ReportSummary* summary = nullptr;
  bool disabled = false;  // after gnuplot turned out to be unusable
  int failures = 0;
};

// Renders one plot; on success returns "plots/NAME.svg".
std::string plot(PlotRun& run, const PlotSpec& spec) {
  if (run.disabled) return {};
  const auto r = render_plot(run.gnuplot, run.plots_dir, spec);
  if (r.ok) {
    run.summary->plots.push_back(r.file);
    return "plots/" + r.file.filename().string();
  }
  run.summary->warnings.push_back(r.message);
  // A gnuplot that cannot run at all (not executable, crashes at once) fails every plot: stop trying.
  if (++run.failures >= 2 && run.summary->plots.empty()) {
    run.disabled = true;
    run.summary->warnings.push_back("gnuplot fails; the remaining plots were skipped");
  }
  return {};
}

std::string axis_label(const std::string& name, const std::string& unit, const std::string& fallback) {
  std::string s = name.empty() ? fallback : name;
  if (!unit.empty() && unit != "-") s += " [" + unit + "]";
  return s;
}

void make_plots(Fit& fit, PlotRun& run, std::string& scalar_plot, std::string& convergence_plot) {
  int index = 0;
  for (auto& e : fit.experiments) {
    ++index;
    if (e.scalar || !e.have_csv) continue;
    char num[16];
    std::snprintf(num, sizeof num, "%02d", index);
    const std::string stem = std::string(num) + "_" + safe_file_stem(e.name);
    const std::string xl = axis_label(e.x.empty() ? e.x_column : e.x, e.x_unit, "x");
    const std::string yl = axis_label(e.y, e.y_unit, "y");

    PlotSpec f;
    f.stem = stem + "_fit";
    f.title = e.name + ": data and simulation";
    f.xlabel = xl;
    f.ylabel = yl;
    f.series.push_back({"measured", e.xs, e.measured, Series::Style::points, ""});
    f.series.push_back({"initial simulation", e.xs, e.initial, Series::Style::dashed_line, ""});
    f.series.push_back({"fitted simulation", e.xs, e.final_, Series::Style::line, "#d62728"});
    // Keep the data readable when the starting guess is far off: clip it to 3x the data span.
    double lo = INFINITY, hi = -INFINITY, ilo = INFINITY, ihi = -INFINITY;
    for (std::size_t i = 0; i < e.measured.size(); ++i) {
      for (double v : {e.measured[i], e.final_[i]}) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      }
      if (std::isfinite(e.initial[i])) ilo = std::min(ilo, e.initial[i]), ihi = std::max(ihi, e.initial[i]);
    }
    if (hi > lo && ihi >= ilo && std::max(hi, ihi) - std::min(lo, ilo) > 3.0 * (hi - lo)) {
      f.has_yrange = true;
      f.ymin = lo - 0.5 * (hi - lo);
      f.ymax = hi + 0.5 * (hi - lo);
      f.series[1].title = "initial simulation (clipped)";
    }
    e.fit_plot = plot(run, f);

    PlotSpec r;
    r.stem = stem + "_residuals";
    const bool sigma = e.cond == Conditioning::noise;
    r.title = e.name + ": residuals of the fit";
    r.xlabel = xl;
    r.ylabel = sigma ? "(fitted - measured) / noise σ" : "(fitted - measured) / scale";
    r.key = false;
    std::vector<double> res(e.measured.size());
    for (std::size_t i = 0; i < res.size(); ++i) res[i] = (e.final_[i] - e.measured[i]) / e.scale;
    r.series.push_back({"fitted - measured", e.xs, res, Series::Style::linespoints, "#1f77b4"});
    r.hlines.push_back({0.0, false});
    if (sigma) {
      r.hlines.push_back({1.0, true});
      r.hlines.push_back({-1.0, true});
    }
    e.residual_plot = plot(run, r);
  }

  PlotSpec s;
  s.stem = "scalars";
  s.title = "scalar experiments: (fitted - measured) / scale";
  s.xlabel = "experiment";
  s.ylabel = "residual / scale (σ when noise is given)";
  Series bars{"fitted - measured", {}, {}, Series::Style::bars, ""};
  Series conflicts{"in conflict", {}, {}, Series::Style::bars, "#d62728"};
  bool any_noise = false;
  for (const auto& e : fit.experiments) {
    if (!e.scalar || !e.have_csv) continue;
    Series& into = e.level == 2 ? conflicts : bars;
    into.x.push_back(static_cast<double>(s.categories.size()));
    into.y.push_back((e.final_[0] - e.measured[0]) / e.scale);
    s.categories.push_back(e.name);
    any_noise = any_noise || e.cond == Conditioning::noise;
  }
  if (!s.categories.empty()) {
    s.series.push_back(bars);
    s.series.push_back(conflicts);
    s.key = false;
    s.hlines.push_back({0.0, false});
    if (any_noise) {
      s.hlines.push_back({1.0, true});
      s.hlines.push_back({-1.0, true});
    }
    double m = 1.2;
    for (const auto* b : {&bars, &conflicts}) {
      for (double v : b->y) {
        if (std::isfinite(v)) m = std::max(m, 1.15 * std::abs(v));
      }
    }
    s.has_yrange = true;
    s.ymin = -m;
    s.ymax = m;
    s.width = std::max(520, std::min(1000, 160 + 90 * static_cast<int>(s.categories.size())));
    scalar_plot = plot(run, s);
  }

  if (!fit.history.empty()) {
    PlotSpec c;
    c.stem = "convergence";
    c.title = "convergence: cost per iteration";
    c.xlabel = (fit.algorithm == "levenberg_marquardt" || fit.algorithm == "dogleg" || fit.algorithm.empty())
                   ? "iteration" : "improvement (objective evaluations that lowered the cost)";
    c.ylabel = "cost (log scale)";
    c.log_y = true;
    c.key = false;
    c.integer_x = true;
    Series h{"cost", {}, fit.history, Series::Style::linespoints, "#2ca02c"};
    for (std::size_t i = 0; i < fit.history.size(); ++i) h.x.push_back(static_cast<double>(i));
    c.series.push_back(h);
    convergence_plot = plot(run, c);
  }
}

// ---------------------------------------------------------------- the report

Cell cell(std::string t, std::string cls = "") { return Cell{std::move(t), std::move(cls), kNaN}; }

std::string conditioning_text(const Experiment& e) {
  switch (e.cond) {
    case Conditioning::noise: return "noise σ = " + with_unit(fmt(e.scale, 4), e.y_unit);
    case Conditioning::range: return "data range " + with_unit(fmt(e.scale, 4), e.y_unit) + " (no noise given)";
    case Conditioning::relative: return "|value| " + fmt(e.scale, 4) + " (no noise given)";
    case Conditioning::unknown: break;
  }
  return "scale " + fmt(e.scale, 4);
}

Doc build(const Fit& fit, const std::vector<Finding>& findings, const std::string& scalar_plot, const std::string& convergence_plot,
          bool plots_requested) {
  Doc d;
  d.title = "Fit report: " + (fit.name.empty() ? std::string("(unnamed fit)") : fit.name);
  Inline intro{{"Fit file "}, {fit.fit_file.empty() ? "(unknown)" : fit.fit_file, false, true}};
  if (!fit.version.empty()) intro.push_back({", spifit " + fit.version});
  intro.push_back({". Fitted card: "});
  intro.push_back({"card.toml", false, true, "card.toml"});
  intro.push_back({"; all numbers: "});
  intro.push_back({"fit.json", false, true, "fit.json"});
  intro.push_back({"."});
  d.para(intro);

  // Warnings first, in plain words.
  std::vector<Inline> warn, notes;
  for (const auto& f : findings) (f.level == 2 ? warn : notes).push_back({{f.text}});
  d.heading(2, "Warnings", "warnings");
  if (!warn.empty()) {
    d.callout("warn", "WARNING: " + std::to_string(warn.size()) + (warn.size() == 1 ? " problem needs attention" : " problems need attention"), warn);
  } else {
    d.callout("ok", "No warnings", {{{"The fit converged, every parameter is identifiable and within its bounds, and every experiment agrees with the fitted model."}}});
  }
  if (!notes.empty()) d.callout("note", "Notes", notes);

  d.heading(2, "Summary", "summary");
  Table s;
  s.id = "summary";
  s.header = {"item", "value"};
  auto row = [&](const std::string& k, const std::string& v, const std::string& cls = "") { s.rows.push_back({cell(k), cell(v, cls)}); };
  row("fit file", fit.fit_file.empty() ? "n/a" : fit.fit_file);
  row("algorithm", fit.algorithm.empty() ? "n/a" : fit.algorithm);
  row("termination", fit.termination.empty() ? "n/a" : fit.termination);
  const bool ceres = fit.algorithm == "levenberg_marquardt" || fit.algorithm == "dogleg";
  if (fit.has_seed && !ceres) row("seed", fmt(fit.seed, 12));
  if (fit.has_usable) row("result usable", fit.usable ? "yes" : "NO", fit.usable ? "good" : "bad");
  row("iterations", fmt(fit.iterations, 10));
  row("forward runs", fmt(fit.forward_runs, 12));
  row("wall time", std::isfinite(fit.wall) ? fmt(fit.wall, 3) + " s" : "n/a");
  row("cost initial", fmt(fit.cost_initial));
  row("cost final", fmt(fit.cost_final));
  if (std::isfinite(fit.cost_initial) && std::isfinite(fit.cost_final) && fit.cost_final > 0) {
    row("cost reduction", "factor " + fmt(fit.cost_initial / fit.cost_final, 4));
  }
  row("residuals / free parameters / degrees of freedom", fmt(fit.m, 10) + " / " + fmt(fit.p, 10) + " / " + fmt(fit.dof, 10));
  bool all_noise = !fit.experiments.empty();
  for (const auto& x : fit.experiments) all_noise = all_noise && x.cond == Conditioning::noise;
  if (std::isfinite(fit.sigma2)) {
    row("σ² = SSE / dof", fmt(fit.sigma2, 4) + (std::isfinite(fit.sigma2) ? " (rms residual " + fmt(std::sqrt(fit.sigma2), 3) + ")" : ""),
        all_noise && fit.sigma2 > kCurveConflictRms * kCurveConflictRms ? "bad" : "");
  }
  d.table(s);
  d.para({{"Cost = " + (fit.cost_definition.empty() ? std::string("1/2 sum of squared conditioned residuals") : fit.cost_definition) +
           ". When noise is given for every experiment, σ² near 1 means the residuals are as large as the stated noise."}});

  d.heading(2, "Parameters", "parameters");
  Table p;
  p.id = "parameters";
  p.header = {"parameter", "initial", "value", "std. error", "95 % interval", "lower", "upper", "identifiable", "note"};
  p.right = {false, true, true, true, true, true, true, false, false};
  for (const auto& q : fit.params) {
    std::string note;
    if (!q.at_bound.empty()) note = "AT " + q.at_bound + " BOUND";
    if (q.log_scale) note += std::string(note.empty() ? "" : "; ") + "log scale";
    const std::string ci = (std::isfinite(q.ci_lo) && std::isfinite(q.ci_hi)) ? "[" + fmt(q.ci_lo) + ", " + fmt(q.ci_hi) + "]" : "n/a";
    const std::string ident = !q.has_uncertainty ? "n/a" : q.identifiable ? "yes" : "NO";
    p.rows.push_back({cell(q.name), cell(fmt(q.initial)), cell(fmt(q.value), q.at_bound.empty() ? "" : "bad"), cell(fmt(q.std_error, 4)), cell(ci),
                      cell(fmt(q.lower)), cell(fmt(q.upper)), cell(ident, q.identifiable ? "" : "bad"), cell(note, q.at_bound.empty() ? "" : "bad")});
  }
  d.table(p);
  d.para({{"Standard errors and 95 % intervals are linearised at the solution (covariance σ² (JᵀJ)⁻¹, Student t quantile " +
           fmt(fit.t975, 4) + "); they assume the model is right and the residuals are independent."}});
  if (!fit.fixed.empty()) {
    Table fx;
    fx.id = "fixed";
    fx.header = {"fixed parameter", "value"};
    for (const auto& [k, v] : fit.fixed) fx.rows.push_back({cell(k), cell(v)});
    d.table(fx);
  }

  d.heading(2, "Experiments", "experiments");
  Table e;
  e.id = "experiments";
  e.header = {"experiment", "kind", "points", "observable", "residuals divided by", "weight", "cost", "share of cost", "share of points", "rms", "verdict"};
  e.right = {false, false, true, false, false, true, true, true, true, true, false};
  for (const auto& x : fit.experiments) {
    std::string obs = x.y.empty() ? "n/a" : x.y;
    if (!x.y_unit.empty() && x.y_unit != "-") obs += " [" + x.y_unit + "]";
    if (!x.scalar && !x.x.empty()) obs += " vs " + axis_label(x.x, x.x_unit, "x");
    const std::string vcls = x.level == 2 ? "bad" : x.level == 1 ? "warn" : "good";
    e.rows.push_back({cell(x.name), cell(x.kind), cell(std::to_string(x.points)), cell(obs), cell(conditioning_text(x)), cell(fmt(x.weight, 4)),
                      cell(fmt(x.cost, 4)), cell(fmt_pct(x.share_cost), x.level == 2 ? "bad" : ""), cell(fmt_pct(x.share_points)),
                      cell(fmt(x.rms, 4), x.level == 2 ? "bad" : ""), cell(x.verdict, vcls)});
  }
  d.table(e);
  d.para({{"rms is the root-mean-square of the conditioned residuals (fitted - measured) / divisor. With the measurement noise as "
           "divisor it should be about 1; far above 1 means these data disagree with the model (or with the other experiments), "
           "well below 1 means the noise is overstated. An experiment with a large share of the cost but few points pulls the fit "
           "towards itself."}});

  if (!fit.alone.empty()) {
    d.heading(3, "Each experiment fitted alone", "per-experiment");
    Table a;
    a.id = "per-experiment";
    a.header = {"fitted to"};
    a.right = {false};
    for (const auto& q : fit.params) {
      a.header.push_back(q.name);
      a.right.push_back(true);
    }
    auto interval = [](double v, double lo, double hi) {
      std::string t = fmt(v, 4);
      if (std::isfinite(lo) && std::isfinite(hi)) t += " [" + fmt(lo, 4) + ", " + fmt(hi, 4) + "]";
      return t;
    };
    std::vector<Cell> joint{cell("all experiments (the fit)")};
    for (const auto& q : fit.params) joint.push_back(cell(interval(q.value, q.ci_lo, q.ci_hi)));
    a.rows.push_back(joint);
    for (const auto& al : fit.alone) {
      std::vector<Cell> r{cell(al.experiment + (al.usable ? "" : " (failed)"), al.usable ? "" : "bad")};
      for (std::size_t k = 0; k < fit.params.size(); ++k) {
        const auto& v = al.values[k];
        const double joint_value = fit.params[k].value;
        if (!v.present || !al.usable) r.push_back(cell("n/a"));
        else if (!v.identifiable) r.push_back(cell("not determined"));
        else {
          const bool excludes = std::isfinite(v.lo) && std::isfinite(v.hi) && (joint_value < v.lo || joint_value > v.hi);
          r.push_back(cell(interval(v.value, v.lo, v.hi), excludes ? "warn" : ""));
        }
      }
      a.rows.push_back(r);
    }
    d.table(a);
    d.para({{"Value and 95 % interval of each parameter when only that experiment is fitted (from the joint solution). "
             "Experiments whose intervals do not overlap disagree on the parameter (listed under Warnings); a highlighted "
             "interval does not contain the joint value. \"not determined\": the experiment alone does not fix the parameter."}});
  }

  if (fit.has_multi) {
    const auto& m = fit.multi;
    d.heading(3, "Multi-start", "multistart");
    d.para({{std::to_string(m.starts) + " starts; the best is start " + (m.best_start >= 0 ? std::to_string(m.best_start) : std::string("n/a")) +
             "; " + (m.at_best >= 0 ? std::to_string(m.at_best) : std::string("n/a")) + " reached the best cost."}});
    Table t;
    t.id = "multistart";
    t.header = {"start", "usable", "cost"};
    t.right = {true, false, true};
    for (const auto& q : fit.params) {
      t.header.push_back(q.name);
      t.right.push_back(true);
    }
    std::vector<Cell> spread{cell("spread at the best cost"), cell(""), cell("")};
    for (std::size_t k = 0; k < fit.params.size(); ++k) {
      const bool ok = k < m.spread_min.size() && std::isfinite(m.spread_min[k]) && std::isfinite(m.spread_max[k]);
      spread.push_back(cell(ok ? fmt(m.spread_min[k]) + " to " + fmt(m.spread_max[k]) : "n/a"));
    }
    t.rows.push_back(spread);
    const std::size_t shown = std::min<std::size_t>(m.solutions.size(), 30);
    for (std::size_t i = 0; i < shown; ++i) {
      const auto& so = m.solutions[i];
      std::vector<Cell> r{cell(std::to_string(i) + (static_cast<int>(i) == m.best_start ? " (best)" : "")), cell(so.usable ? "yes" : "no", so.usable ? "" : "warn"),
                          cell(fmt(so.cost))};
      for (std::size_t k = 0; k < fit.params.size(); ++k) r.push_back(cell(k < so.values.size() ? fmt(so.values[k]) : "n/a"));
      t.rows.push_back(r);
    }
    d.table(t);
    if (m.solutions.size() > shown) d.para({{"(first " + std::to_string(shown) + " of " + std::to_string(m.solutions.size()) + " starts shown; all are in fit.json)"}});
  }

  bool any_scalar = false;
  for (const auto& x : fit.experiments) any_scalar = any_scalar || x.scalar;
  if (any_scalar) {
    d.heading(3, "Scalar experiments", "scalars");
    Table sc;
    sc.id = "scalars";
    sc.header = {"experiment", "observable", "measured", "initial", "fitted", "fitted - measured", "(fitted - measured) / divisor"};
    sc.right = {false, false, true, true, true, true, true};
    for (const auto& x : fit.experiments) {
      if (!x.scalar) continue;
      if (!x.have_csv) {
        sc.rows.push_back({cell(x.name), cell(x.y), cell("n/a"), cell("n/a"), cell("n/a"), cell("n/a"), cell("n/a")});
        continue;
      }
      const double diff = x.final_[0] - x.measured[0];
      sc.rows.push_back({cell(x.name), cell(with_unit(x.y, x.y_unit)), cell(fmt(x.measured[0])), cell(fmt(x.initial[0])), cell(fmt(x.final_[0])),
                         cell(fmt(diff, 4)), cell(fmt(diff / x.scale, 3), x.level == 2 ? "bad" : "")});
    }
    d.table(sc);
    if (!scalar_plot.empty()) d.figure(scalar_plot, "Scalar experiments: (fitted - measured) / divisor; dashed lines at ±1, red: in conflict");
  }

  bool any_curve = false;
  for (const auto& x : fit.experiments) any_curve = any_curve || !x.scalar;
  if (any_curve) {
    d.heading(2, "Curves: data and fit", "curves");
    for (const auto& x : fit.experiments) {
      if (x.scalar) continue;
      d.heading(3, x.name);
      if (!x.have_csv) {
        d.para({{"No data: " + (x.data_file.empty() ? std::string("experiments/") + x.name + ".csv" : x.data_file) + " could not be read."}});
        continue;
      }
      std::string line = std::to_string(x.measured.size()) + " points; " + x.verdict;
      if (x.sign_changes >= 0) {
        line += "; the residual changes sign " + std::to_string(x.sign_changes) + " times (about " + fmt_fixed(x.expected_sign_changes, 0) +
                " expected for independent noise)";
      }
      d.para({{line + "."}});
      if (!x.fit_plot.empty()) d.figure(x.fit_plot, x.name + ": measured points, initial (dashed) and fitted simulation");
      if (!x.residual_plot.empty()) {
        d.figure(x.residual_plot, x.name + ": residuals (fitted - measured) / divisor" +
                                      std::string(x.cond == Conditioning::noise ? "; dashed lines at ±1 σ" : ""));
      }
    }
  }

  d.heading(2, "Convergence", "convergence");
  if (!convergence_plot.empty()) d.figure(convergence_plot, "Cost per iteration (log scale)");
  if (!fit.history.empty() && fit.history.size() <= 40) {
    Table h;
    h.id = "convergence";
    h.header = {"iteration", "cost"};
    h.right = {true, true};
    for (std::size_t i = 0; i < fit.history.size(); ++i) h.rows.push_back({cell(std::to_string(i)), cell(fmt(fit.history[i], 8))});
    d.table(h);
  } else if (fit.history.empty()) {
    d.para({{"No cost history in fit.json."}});
  } else {
    d.para({{std::to_string(fit.history.size()) + " iterations; first cost " + fmt(fit.history.front()) + ", last " + fmt(fit.history.back()) + "."}});
  }

  d.heading(2, "Correlation of the parameters", "correlation");
  if (fit.corr.empty() || fit.corr.size() != fit.corr_names.size()) {
    d.para({{"No correlation matrix in fit.json."}});
  } else {
    Table c;
    c.id = "correlation";
    c.header.push_back("");
    c.right.push_back(false);
    for (const auto& n : fit.corr_names) {
      c.header.push_back(n);
      c.right.push_back(true);
    }
    for (std::size_t a = 0; a < fit.corr.size(); ++a) {
      std::vector<Cell> r{cell(fit.corr_names[a])};
      for (std::size_t b = 0; b < fit.corr[a].size(); ++b) {
        const double v = fit.corr[a][b];
        Cell x = cell(fmt_fixed(v, 3));
        if (a == b) x.cls = "diag";
        else if (std::isfinite(v) && std::abs(v) >= kCorrWarn) x.cls = "bad";
        else x.shade = v;
        r.push_back(x);
      }
      c.rows.push_back(r);
    }
    d.table(c);
    d.para({{"|r| near 1: the two parameters compensate each other; the data fix a combination of them, not each one."}});
  }

  d.heading(2, "Singular values", "singular-values");
  if (fit.singular_values.empty()) {
    d.para({{"No singular values in fit.json."}});
  } else {
    Table sv;
    sv.id = "singular-values";
    sv.header = {"#", "singular value", "relative to the largest"};
    sv.right = {true, true, true};
    double mx = 0.0;
    for (double v : fit.singular_values) {
      if (std::isfinite(v)) mx = std::max(mx, v);
    }
    for (std::size_t i = 0; i < fit.singular_values.size(); ++i) {
      const double rel = mx > 0 ? fit.singular_values[i] / mx : kNaN;
      sv.rows.push_back({cell(std::to_string(i + 1)), cell(fmt(fit.singular_values[i], 4)), cell(fmt(rel, 3), std::isfinite(rel) && rel < 1e-8 ? "bad" : "")});
    }
    d.table(sv);
    d.para({{"Singular values of the Jacobian scaled by the parameter magnitudes (relative sensitivities). Condition number " +
             fmt(fit.condition, 4) + ". A singular value near zero marks a parameter combination the experiments cannot see."}});
  }

  d.heading(2, "Files", "files");
  std::vector<Inline> files{{{"card.toml", false, true, "card.toml"}, {": the fitted material card"}},
                            {{"fit.json", false, true, "fit.json"}, {": every number of this report"}}};
  for (const auto& x : fit.experiments) {
    const std::string f = x.data_file.empty() ? "experiments/" + x.name + ".csv" : x.data_file;
    files.push_back({{f, false, true, inside(f).empty() ? "" : f}, {": measured and simulated values of " + x.name}});
  }
  if (plots_requested) {
    files.push_back({{"plots/", false, true}, {": the plots (SVG); plots/src/ holds their gnuplot scripts and data (cd plots && gnuplot src/NAME.gp)"}});
  }
  d.list(files);
  return d;
}


}  // namespace

ReportSummary render_fit_report(const fs::path& dir, const ReportOptions& options) {
  ReportSummary summary;
  Fit fit = load_fit(dir);

  for (auto& e : fit.experiments) {
    fs::path rel = inside(e.data_file);
    if (rel.empty()) rel = inside("experiments/" + e.name + ".csv");
    std::string why = "experiment " + e.name + ": no safe data file name";
    if (rel.empty() || !read_experiment_csv(dir / rel, e, why)) {
      summary.warnings.push_back(why + "; no table or plot for it");
      continue;
    }
    if (e.scalar && e.measured.size() != 1) {
      e.have_csv = false;
      summary.warnings.push_back((dir / rel).string() + ": a scalar experiment needs exactly one row");
    }
  }

  const auto findings = analyse(fit);
  for (const auto& f : findings) {
    if (f.level == 2) summary.findings.push_back(f.text);
  }

  std::string scalar_plot, convergence_plot;
  if (options.plots) {
    PlotRun run;
    run.summary = &summary;
    run.plots_dir = dir / "plots";
    run.gnuplot = find_executable(options.gnuplot);
    if (run.gnuplot.empty()) {
      summary.warnings.push_back("gnuplot (" + options.gnuplot + ") not found; the report has no plots (Debian: apt-get install gnuplot-nox)");
    } else {
      try {
        make_plots(fit, run, scalar_plot, convergence_plot);
      } catch (const std::exception& ex) {  // never fail the report because of a plot
        summary.warnings.push_back(std::string("plots: ") + ex.what());
      }
    }
  }

  const Doc doc = build(fit, findings, scalar_plot, convergence_plot, !summary.plots.empty());
  summary.markdown = dir / "report.md";
  summary.html = dir / "report.html";
  io::write_file_atomic(summary.markdown, to_markdown(doc));
  io::write_file_atomic(summary.html, to_html(doc));
  return summary;
}

}  // namespace spifit::reports
