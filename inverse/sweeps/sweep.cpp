// The sweep engine: grid points and sensitivity runs of any scene kind (sweep.hpp).
#include "inverse/sweeps/sweep.hpp"

#include "forward/io/binary_archive.hpp"
#include "forward/io/csv_writer.hpp"
#include "forward/scenes/common/run_files.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

namespace spifit::inverse {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The metrics of a run: a failed run keeps its counts (iterations, increments); its forces and
// shapes do not describe the whole path.
std::vector<double> metrics_of(const SweepSpec& s, const std::vector<const scene::Observable*>& observables,
                               const scene::SceneResult& r) {
  std::vector<double> out;
  for (const scene::Observable* o : observables) out.push_back(r.ok() || o->counts_failed_runs ? o->value(r, s.options) : kNaN);
  return out;
}

// d ln(metric) / d ln(input) = (input / metric) d metric / d input of the metrics with
// derivatives (s.exact_metrics), from a run with sensitivities with respect to the inputs.
std::vector<double> log_derivatives_of(const SweepSpec& s, const std::vector<const scene::Observable*>& observables, const scene::SceneResult& r,
                                       const std::vector<double>& inputs, const std::vector<double>& metrics) {
  std::vector<double> out;
  for (int m : s.exact_metrics) {
    const auto um = static_cast<std::size_t>(m);
    const std::vector<double> d = r.ok() ? observables[um]->derivatives(r, s.options) : std::vector<double>{};
    for (std::size_t k = 0; k < s.inputs.size(); ++k)
      out.push_back(d.size() == s.inputs.size() && metrics[um] != 0.0 ? d[k] * inputs[k] / metrics[um] : kNaN);
  }
  return out;
}

// The kind's observables behind s.metrics, looked up once per sweep (read_sweep_file has checked
// the names; a spec built in code gets the same error).
std::vector<const scene::Observable*> observables_of(const SweepSpec& s) {
  std::vector<const scene::Observable*> out;
  for (const auto& name : s.metrics) {
    const scene::Observable* o = s.kind->find_observable(name);
    if (!o) throw std::invalid_argument("scene kind " + s.kind->name + " has no observable \"" + name + "\"");
    out.push_back(o);
  }
  return out;
}

// One run of the scene with the inputs at `values`; its outputs in DIR/sub/ when dir is given.
// record: list DIR's new entries in its manifest (not on a worker process of an MPI job: the
// sweep's own process lists them at the end).
SweepPoint run_point(const SweepSpec& s, const std::vector<const scene::Observable*>& observables, const std::vector<double>& values,
                     const io::OutputDirectory* dir, const std::string& sub, bool record = true) {
  const auto t0 = std::chrono::steady_clock::now();
  SweepPoint p;
  p.inputs = values;
  try {
    auto sc = s.scene->clone();
    for (std::size_t k = 0; k < s.inputs.size(); ++k) {
      const std::string why = sc->set_input(s.inputs[k].name, values[k]);
      if (!why.empty()) throw std::invalid_argument(s.inputs[k].name + ": " + why);
    }
    std::unique_ptr<scene::SceneResult> r;
    scene::RunControl control;
    if (s.exact)
      for (const auto& in : s.inputs) control.sensitivities.push_back(in.name);
    if (dir) {
      // Under the sweep directory, whose lock the sweep holds.
      const auto out = io::OutputDirectory::prepare((dir->path() / sub).string(), false, {}, io::OutputDirectory::Locking::none);
      if (record) dir->record();  // points/ in the sweep directory's manifest
      r = sc->run(scene::RunFiles(out), control);
    } else {
      r = sc->run(scene::RunFiles(), control);
    }
    p.ok = r->ok();
    p.message = r->message;
    p.metrics = metrics_of(s, observables, *r);
    if (s.exact) p.log_derivatives = log_derivatives_of(s, observables, *r, values, p.metrics);
  } catch (const std::exception& e) {
    p.ok = false;
    p.message = e.what();
    p.metrics.assign(s.metrics.size(), kNaN);
  }
  p.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
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

// One progress line per run of a serial sweep (a parallel kind's runs take milliseconds: none).
void report(const SweepRunOptions& o, const std::string& what, const SweepSpec& s, const SweepPoint& p) {
  if (!o.progress || s.kind->parallel_sweeps) return;
  char buf[120];
  std::snprintf(buf, sizeof buf, " -> %s in %.1f s", p.ok ? "ok" : "failed", p.wall_seconds);
  o.progress({scene::ProgressEvent::Kind::mark, what + ": " + point_label(s, p.inputs) + buf + (p.ok ? "" : ": " + p.message), 0.0});
}

// DIR/points/NNN: zero-padded to at least 3 digits, as many as the largest index needs.
std::string point_dir(std::size_t i, std::size_t n) {
  const int width = std::max(3, static_cast<int>(std::to_string(n > 0 ? n - 1 : 0).size()));
  char buf[32];
  std::snprintf(buf, sizeof buf, "points/%0*zu", width, i);
  return buf;
}

// A point's job and answer as binary archives (exact bits, checked kind and version).
constexpr const char* kPointJobKind = "sweep-point-job";
constexpr const char* kPointAnswerKind = "sweep-point-answer";
constexpr std::uint32_t kPointVersion = 2;  // 2: with the exact log derivatives

std::string point_job(const std::vector<double>& values, const std::string& sub) {
  io::BinaryWriter w(kPointJobKind, kPointVersion);
  w.f64s(values);
  w.string(sub);
  return w.finish();
}

std::string point_answer(const SweepPoint& p) {
  io::BinaryWriter w(kPointAnswerKind, kPointVersion);
  w.f64s(p.inputs);
  w.f64s(p.metrics);
  w.boolean(p.ok);
  w.string(p.message);
  w.f64(p.wall_seconds);
  w.f64s(p.log_derivatives);
  return w.finish();
}

SweepPoint read_point_answer(const std::string& bytes) {
  io::BinaryReader r(bytes, kPointAnswerKind, kPointVersion);
  SweepPoint p;
  p.inputs = r.f64s();
  p.metrics = r.f64s();
  p.ok = r.boolean();
  p.message = r.string();
  p.wall_seconds = r.f64();
  p.log_derivatives = r.f64s();
  r.finish();
  return p;
}

// A run of the sweep: values and, for FE scenes, the subdirectory of its outputs.
struct PointRun {
  std::string label;  // for the progress line
  std::vector<double> values;
  std::string sub;
};

// The runs, here one after another or on the workers of o.pool side by side; the points in the
// order of runs whatever the order they finish in.
std::vector<SweepPoint> run_points(const SweepSpec& s, const std::vector<const scene::Observable*>& obs, const SweepRunOptions& o,
                                   const std::vector<PointRun>& runs) {
  std::vector<SweepPoint> points(runs.size());
  const io::OutputDirectory* dir = s.kind->parallel_sweeps ? nullptr : o.out;
  if (s.kind->parallel_sweeps) {  // milliseconds each: side by side here, no progress lines
    const int n = static_cast<int>(runs.size());
#pragma omp parallel for schedule(dynamic) num_threads(std::max(1, o.threads))
    for (int i = 0; i < n; ++i) points[static_cast<std::size_t>(i)] = run_point(s, obs, runs[static_cast<std::size_t>(i)].values, nullptr, {});
    return points;
  }
  if (!o.pool) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      points[i] = run_point(s, obs, runs[i].values, dir, runs[i].sub);
      report(o, runs[i].label, s, points[i]);
    }
    return points;
  }
  const int n = static_cast<int>(runs.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::max(1, o.pool->workers()))
  for (int i = 0; i < n; ++i) {
    const auto& run = runs[static_cast<std::size_t>(i)];
    SweepPoint p;
    try {
      p = read_point_answer(o.pool->run(point_job(run.values, run.sub)));
    } catch (const std::exception& e) {
      p.inputs = run.values;
      p.metrics.assign(s.metrics.size(), kNaN);
      p.message = std::string("no answer from the worker: ") + e.what();
    }
    points[static_cast<std::size_t>(i)] = p;
#pragma omp critical(spifit_sweep_progress)
    report(o, run.label, s, p);
  }
  if (dir) dir->record();  // points/ and sensitivities/, written by the workers
  return points;
}

std::vector<SweepPoint> run_grid(const SweepSpec& s, const std::vector<const scene::Observable*>& obs, const SweepRunOptions& o) {
  const auto grid = sweep_grid(s);
  std::vector<PointRun> runs;
  for (std::size_t i = 0; i < grid.size(); ++i)
    runs.push_back({"point " + std::to_string(i + 1) + "/" + std::to_string(grid.size()), grid[i], point_dir(i, grid.size())});
  return run_points(s, obs, o, runs);
}

// With exact derivatives: the base run alone; metrics without derivatives get NaN.
std::vector<Sensitivity> run_exact_sensitivities(const SweepSpec& s, const std::vector<const scene::Observable*>& obs, const SweepRunOptions& o) {
  std::vector<double> base;
  for (const auto& in : s.inputs) base.push_back(s.scene->input(in.name));
  const SweepPoint b = run_points(s, obs, o, {{"sensitivity base", base, "sensitivities/base"}}).front();
  std::vector<Sensitivity> r;
  for (std::size_t k = 0; k < s.inputs.size(); ++k) {
    for (std::size_t m = 0; m < s.metrics.size(); ++m) {
      Sensitivity sv{s.inputs[k].name, s.metrics[m], base[k], b.metrics[m], kNaN};
      for (std::size_t e = 0; e < s.exact_metrics.size(); ++e)
        if (static_cast<std::size_t>(s.exact_metrics[e]) == m && b.log_derivatives.size() == s.exact_metrics.size() * s.inputs.size())
          sv.value = b.log_derivatives[e * s.inputs.size() + k];
      r.push_back(sv);
    }
  }
  return r;
}

// Central differences of ln(metric) in ln(input) at the scene's own values (base, base (1 +- h)).
std::vector<Sensitivity> run_sensitivities(const SweepSpec& s, const std::vector<const scene::Observable*>& obs,
                                           const SweepRunOptions& o) {
  if (s.exact) return run_exact_sensitivities(s, obs, o);
  std::vector<double> base;
  bool any = false;
  for (const auto& in : s.inputs) {
    base.push_back(s.scene->input(in.name));
    any = any || (!in.integer && base.back() != 0.0);
  }
  // Integer inputs have no relative step; a zero base has no logarithm: NaN, no runs.
  auto skip = [&](std::size_t k) { return s.inputs[k].integer || base[k] == 0.0; };
  std::vector<PointRun> runs;
  const bool with_base = any || s.kind->parallel_sweeps;  // the base metric is reported even with no step to take
  if (with_base) runs.push_back({"sensitivity base", base, "sensitivities/base"});
  for (std::size_t k = 0; k < s.inputs.size(); ++k) {
    if (skip(k)) continue;
    auto up = base, dn = base;
    up[k] *= 1.0 + s.relative_step;
    dn[k] *= 1.0 - s.relative_step;
    runs.push_back({"sensitivity " + s.inputs[k].name + " up", up, "sensitivities/" + s.inputs[k].name + "_up"});
    runs.push_back({"sensitivity " + s.inputs[k].name + " down", dn, "sensitivities/" + s.inputs[k].name + "_down"});
  }
  const std::vector<SweepPoint> done = run_points(s, obs, o, runs);
  std::size_t next = 0;
  SweepPoint b;
  b.metrics.assign(s.metrics.size(), kNaN);
  if (with_base) b = done[next++];
  std::vector<Sensitivity> r;
  for (std::size_t k = 0; k < s.inputs.size(); ++k) {
    SweepPoint pu, pd;
    if (!skip(k)) {
      pu = done[next++];
      pd = done[next++];
    }
    for (std::size_t m = 0; m < s.metrics.size(); ++m) {
      Sensitivity sv{s.inputs[k].name, s.metrics[m], base[k], b.metrics[m], kNaN};
      if (!skip(k)) sv.value = log_sensitivity(base[k], pu.metrics[m], pd.metrics[m], s.relative_step);
      r.push_back(sv);
    }
  }
  return r;
}

}  // namespace

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
  const auto t0 = std::chrono::steady_clock::now();
  SweepResult r;
  const auto obs = observables_of(s);
  r.points = run_grid(s, obs, o);
  if (s.sensitivities) r.sensitivities = run_sensitivities(s, obs, o);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

JobHandler sweep_point_handler(const SweepSpec& s, const std::string& out) {
  auto dir = std::make_shared<std::optional<io::OutputDirectory>>();
  return [&s, out, dir](const std::string& job) {
    SweepPoint p;
    try {
      io::BinaryReader r(job, kPointJobKind, kPointVersion);
      const std::vector<double> values = r.f64s();
      const std::string sub = r.string();
      // The sweep (rank 0) holds the directory's lock; its jobs write their points for it.
      if (!*dir && !out.empty()) *dir = io::OutputDirectory::existing(out, io::OutputDirectory::Locking::none);
      p = run_point(s, observables_of(s), values, dir->has_value() ? &**dir : nullptr, sub, false);
    } catch (const std::exception& e) {
      p.ok = false;
      p.message = e.what();
      p.metrics.assign(s.metrics.size(), kNaN);
    }
    return point_answer(p);
  };
}

std::string failed_point_answer(const SweepSpec& s, const std::string& job, const std::string& why) {
  SweepPoint p;
  try {
    io::BinaryReader r(job, kPointJobKind, kPointVersion);
    p.inputs = r.f64s();
  } catch (const std::exception&) {
  }
  p.ok = false;
  p.message = why;
  p.metrics.assign(s.metrics.size(), kNaN);
  return point_answer(p);
}

std::string sweep_csv(const SweepSpec& s, const SweepResult& r) {
  std::vector<std::string> cols;
  for (const auto& in : s.inputs) cols.push_back(in.name);
  for (const auto& m : s.metrics) cols.push_back(m);
  for (int m : s.exact_metrics)
    for (const auto& in : s.inputs) cols.push_back("dln(" + s.metrics[static_cast<std::size_t>(m)] + ")/dln(" + in.name + ")");
  cols.push_back("wall_seconds");
  cols.push_back("ok");
  io::CsvTable t(cols);
  const std::size_t derivatives = s.exact_metrics.size() * s.inputs.size();
  for (const auto& p : r.points) {
    std::vector<double> row = p.inputs;
    row.insert(row.end(), p.metrics.begin(), p.metrics.end());
    for (std::size_t i = 0; i < derivatives; ++i) row.push_back(i < p.log_derivatives.size() ? p.log_derivatives[i] : kNaN);
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
