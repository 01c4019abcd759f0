#pragma once
// The shell element's obstacle course (docs/results/validation.md): each benchmark builds its mesh,
// material, supports and loads, says whether it is a linear or a nonlinear analysis, and
// extracts one value to compare with a published or closed-form reference. Sources and
// normalisations: docs/results/validation.md.
#include "forward/mesh/mesh.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/newton_solver.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spifit::scene {

struct ShellBenchmarkSetup {
  std::string benchmark;      // see shell_benchmark_names()
  int mesh = 0;               // elements per side / along the length; 0 = the benchmark's default
  int thickness_points = 0;   // 0 = the benchmark's default
  element::ThicknessRuleKind thickness_rule = element::ThicknessRuleKind::gauss;
  // Five unknowns at every node with free rotations (ShellModel::use_nodal_rotation_frames);
  // false keeps six (tests compare the two).
  bool rotation_frames = true;
};

// A model ready to solve. `mesh` is owned here and outlives `model`.
struct ShellBenchmark {
  std::string benchmark;
  std::string quantity;   // what `value` is, with units
  std::string source;     // where the reference comes from
  double reference = 0.0;
  bool linear = false;    // linear analysis (one solve) or nonlinear increments
  solver::NewtonOptions solver;  // the benchmark's defaults
  std::unique_ptr<mesh::Mesh> mesh;
  std::unique_ptr<model::ShellModel> model;
  std::unique_ptr<solver::DofConstraints> constraints;
  double thickness = 0.0;
  element::ThicknessRuleKind thickness_rule = element::ThicknessRuleKind::gauss;
  std::function<double(model::ShellModel&)> value;
  std::function<nlohmann::json(model::ShellModel&)> details;  // extra numbers for summary.json
};

std::vector<std::string> shell_benchmark_names();
std::string shell_benchmark_defaults(const std::string& name);  // "mesh 16, 5 thickness points"

// Throws std::invalid_argument on an unknown benchmark or meaningless mesh/point counts.
ShellBenchmark make_shell_benchmark(const ShellBenchmarkSetup& setup);

}  // namespace spifit::scene
