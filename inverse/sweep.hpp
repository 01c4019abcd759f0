#pragma once
// Sensitivity studies (SPEC §6): a scene run over a grid of one or more named inputs, with
// scalar metrics, wall seconds and status per point, plus local normalised sensitivities
// d ln(metric) / d ln(input) at the base point by central differences.
// Material-point scenes: inputs are material parameters, points run in parallel (OpenMP,
// results stored by grid index so the output order is fixed). Forming scenes (indent,
// indent_line, line; inverse/forming_sweep.hpp): inputs may also be scene keys (contact,
// tool, solver, sheet), points run one after another (each run is itself parallel) and each
// writes its outputs to DIR/points/NNN/.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/forming_scene.hpp"
#include "forward/scenes/scene_file.hpp"
#include "inverse/parameters.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace spifit::inverse {

struct SweepInput {
  std::string name;             // a parameter name (parameters.hpp) or a forming scene key
  std::vector<double> values;
};

// The forming part of a sweep: the base scene and the travel window of the window metrics.
struct FormingSweepSetup {
  scene::FormingScene scene;                   // its values (and card) are the base point
  std::optional<std::array<double, 2>> window;  // [from, to] mm of tool travel
};

struct SweepSpec {
  std::string name, file;
  scene::MaterialPointScene scene;   // material-point sweeps: its card is the base point
  std::optional<FormingSweepSetup> forming;  // set for forming sweeps (then `scene` is unused)
  std::vector<SweepInput> inputs;
  std::vector<std::string> metrics;  // sweep_metric_names() or forming_metric_names()
  bool sensitivities = true;         // default: true for material points, false for forming scenes
  double relative_step = 0.01;       // for the sensitivities
};

struct SweepPoint {
  std::vector<double> inputs;
  std::vector<double> metrics;  // NaN where not available
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

// Material-point metrics.
const char* sweep_metric_names();
bool is_sweep_metric(const std::string& name);

// Throws io::InputError naming file, key and value.
SweepSpec read_sweep_file(const std::string& path);
// Files the sweep reads (sweep file, scene, card, G-code): never inside the output directory.
std::vector<std::string> sweep_input_files(const SweepSpec& spec);

struct SweepRunOptions {
  int threads = 1;                        // material-point sweeps (forming runs use OpenMP's default)
  const io::OutputDirectory* out = nullptr;  // required for forming sweeps: DIR/points/NNN/
  bool progress = false;                  // forming sweeps: one line per point on stderr
};
SweepResult run_sweep(const SweepSpec& spec, const SweepRunOptions& options);
SweepResult run_sweep(const SweepSpec& spec, int threads);  // material-point sweeps

// The grid in run order: Cartesian product of the inputs' values, last input fastest.
std::vector<std::vector<double>> sweep_grid(const SweepSpec& spec);
// d ln(metric) / d ln(input) from runs at base (1 +- h): NaN when the base input is 0 or the
// two metrics do not share a sign.
double log_sensitivity(double base_input, double metric_up, double metric_down, double h);

std::string sweep_csv(const SweepSpec& spec, const SweepResult& r);
std::string sensitivities_csv(const SweepResult& r);

}  // namespace spifit::inverse
