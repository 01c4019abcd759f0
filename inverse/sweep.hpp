#pragma once
// Sensitivity studies (SPEC §6): a scene run over a grid of one or more named inputs, in
// parallel (OpenMP, results stored by grid index so the output order is fixed), with scalar
// metrics, wall seconds and status per point, plus local normalised sensitivities
// d ln(metric) / d ln(input) at the base point by central differences.
#include "forward/scenes/scene_file.hpp"
#include "inverse/parameters.hpp"

#include <string>
#include <vector>

namespace spifit::inverse {

struct SweepInput {
  std::string name;             // a parameter name (parameters.hpp)
  std::vector<double> values;
};

struct SweepSpec {
  std::string name, file;
  scene::MaterialPointScene scene;   // its card is the base point
  std::vector<SweepInput> inputs;
  std::vector<std::string> metrics;  // r_value, yield_stress, initial_yield_stress, reverse_yield_stress, final_stress, max_abs_stress, final_eqps, final_thickness_strain
  bool sensitivities = true;
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

const char* sweep_metric_names();
bool is_sweep_metric(const std::string& name);

// Throws io::InputError naming file, key and value.
SweepSpec read_sweep_file(const std::string& path);
SweepResult run_sweep(const SweepSpec& spec, int threads);
std::string sweep_csv(const SweepSpec& spec, const SweepResult& r);
std::string sensitivities_csv(const SweepResult& r);

}  // namespace spifit::inverse
