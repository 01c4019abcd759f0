#pragma once
// Shell benchmark scene files (kind = "shell_benchmark", experiments/benchmarks/*.toml):
// reading, running and writing DIR/summary.json (value, reference, relative error),
// DIR/increments.csv (convergence report per increment) and DIR/vtu/shell.pvd (ParaView).
// Schema: docs/reference/file-formats.md.
#include "forward/io/series.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/scene_result.hpp"
#include "forward/scenes/benchmark/shell_benchmarks.hpp"
#include "forward/solver/newton_solver.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace spifit::scene {

struct ShellBenchmarkScene {
  std::string name, description, file;
  ShellBenchmarkSetup setup;
  // [solver] overrides of the benchmark's defaults (unset: keep them).
  std::optional<double> initial_increment, min_increment, max_increment, force_tolerance, displacement_tolerance;
  std::optional<int> max_iterations;
  std::optional<bool> line_search;
  std::optional<solver::LinearSolverKind> linear_solver;
  bool vtu = true;
  int vtu_every = 0;  // 0: the final state only; n: every n-th increment and the final one
};

// Throws io::InputError naming file, key and value.
ShellBenchmarkScene read_shell_benchmark_scene(const std::string& path);

class ShellBenchmarkResult final : public SceneResult {
 public:
  nlohmann::json inputs;  // the scene and model as summary.json describes them
  std::string name, benchmark, linear_solver;
  int elements = 0;
  double reference = 0.0, value = 0.0, load_factor = 0.0;
  nlohmann::json details;  // the benchmark's extra numbers (null: none)
  solver::NewtonCounters counters;
  // Newton convergence per increment (increments.csv).
  io::Series increments{{{"increment", ""}, {"load_factor", ""}, {"increment_size", ""}, {"iterations", ""}, {"line_searches", ""},
                         {"final_relative_residual", ""}}};
  nlohmann::json to_json() const override;
  std::string brief_report() const override;
};

// Numerical failures are reported in the result (status "failed", where and why); the
// increments and VTU files written so far are kept.
ShellBenchmarkResult run_shell_benchmark_scene(const ShellBenchmarkScene& scene, const RunFiles& files = {}, const RunControl& control = {});

}  // namespace spifit::scene
