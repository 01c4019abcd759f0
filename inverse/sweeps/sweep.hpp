#pragma once
// Sensitivity studies (docs/design/identification.md, "Sweeps"): a scene of any kind run over a grid of
// one or more named inputs -- the scene kind's own (contact.friction, tool.radius, ...) or the
// card's parameters (hill.N, swift.K, ...) -- with scalar metrics read off each run's typed result
// (the kind's observables), wall seconds and status per point, and local normalised
// sensitivities d ln(metric) / d ln(input) at the base point by central differences. Material
// points run side by side (OpenMP, results stored by grid index so the output order is fixed);
// FE scenes run one after another (each run is itself parallel), each writing its outputs to
// DIR/points/NNN/.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/progress.hpp"
#include "forward/scenes/common/scene.hpp"
#include "inverse/runs/job_pool.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::inverse {

struct SweepInput {
  std::string name;  // a named input of the scene (its kind's or its card's)
  std::vector<double> values;
  bool integer = false;  // no relative step: no sensitivity
};

struct SweepSpec {
  std::string name, file;
  std::shared_ptr<const scene::Scene> scene;  // its values (and card) are the base point
  const scene::SceneKind* kind = nullptr;
  std::vector<SweepInput> inputs;
  std::vector<std::string> metrics;   // the kind's observables
  scene::ObservableOptions options;   // [sweep] window or contours
  bool sensitivities = true;          // default: true for material points, false for FE scenes
  double relative_step = 0.01;        // for the sensitivities
  // [sweep] exact_sensitivities: every FE run carries the exact derivatives with respect to the
  // inputs (RunControl::sensitivities): each point gets d ln(metric) / d ln(input) of the
  // metrics that have derivatives (exact_metrics), and the base point's sensitivities come from
  // its run alone instead of central differences.
  bool exact = false;
  std::vector<int> exact_metrics;  // indices into metrics with derivatives (exact only)
};

struct SweepPoint {
  std::vector<double> inputs;
  std::vector<double> metrics;  // NaN where not available
  // exact: per metric of exact_metrics, per input: d ln(metric) / d ln(input) (NaN where not
  // available)
  std::vector<double> log_derivatives;
  bool ok = false;
  std::string message;
  double wall_seconds = 0.0;
};

struct Sensitivity {
  std::string input, metric;
  double base_input = 0.0, base_metric = 0.0, value = 0.0;  // d ln(metric) / d ln(input)
};

struct SweepResult {
  std::vector<SweepPoint> points;
  std::vector<Sensitivity> sensitivities;
  double wall_seconds = 0.0;
};

// Throws io::InputError naming file, key and value (an unknown input or metric, a value the
// scene cannot take, alone or at a grid point with the other inputs).
SweepSpec read_sweep_file(const std::string& path);
// Files the sweep reads (sweep file, scene, card, G-code): never inside the output directory.
std::vector<std::string> sweep_input_files(const SweepSpec& spec);

struct SweepRunOptions {
  int threads = 1;                           // material points side by side (FE runs: OpenMP's default inside)
  const io::OutputDirectory* out = nullptr;  // FE scenes: DIR/points/NNN/ (none: runs in memory)
  scene::ProgressSink progress;              // one line per point
  // FE scenes: other processes that run the points side by side (an MPI job; null: this one,
  // one point after another). The points come back in grid order.
  JobPool* pool = nullptr;
};
SweepResult run_sweep(const SweepSpec& spec, const SweepRunOptions& options);
// The worker's side of a pool: runs a point into DIR/points/NNN of the sweep's output directory
// out (prepared by the sweep's own process; "": in memory), not touching its manifest.
JobHandler sweep_point_handler(const SweepSpec& spec, const std::string& out);
// The answer of a point job that could not be run (why: e.g. its process died twice): a failed
// point with the job's inputs.
std::string failed_point_answer(const SweepSpec& spec, const std::string& job, const std::string& why);

// The grid in run order: Cartesian product of the inputs' values, last input fastest.
std::vector<std::vector<double>> sweep_grid(const SweepSpec& spec);
// d ln(metric) / d ln(input) from runs at base (1 +- h): NaN when the base input is 0 or the
// two metrics do not share a sign.
double log_sensitivity(double base_input, double metric_up, double metric_down, double h);

std::string sweep_csv(const SweepSpec& spec, const SweepResult& r);
std::string sensitivities_csv(const SweepResult& r);

}  // namespace spifit::inverse
