#pragma once
// Shell benchmark scene files (kind = "shell_benchmark", experiments/benchmarks/*.toml):
// reading, running and writing DIR/summary.json (value, reference, relative error),
// DIR/increments.csv (convergence report per increment) and DIR/vtu/shell.pvd (ParaView).
// Schema: docs/file-formats.md.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/shell_benchmarks.hpp"
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

struct ShellSceneReport {
  bool ok = true;
  nlohmann::json summary;
};

// Numerical failures are reported in the summary (status "failed", where and why); the
// increments and VTU files written so far are kept.
ShellSceneReport run_shell_benchmark_scene(const ShellBenchmarkScene& scene, const io::OutputDirectory& out,
                                           bool progress = false);

}  // namespace spifit::scene
