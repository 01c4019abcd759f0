// Wall time of the bundled FE forming scenes (speed goals on 2 cores: indent < 1 s,
// indent_line < 2 s, line half model < 10 s, full model < 30 s). Each benchmark runs the scene
// file as `spifit run` would (outputs to a temporary directory, removed afterwards) and reports
// the median wall time of its repetitions, the Newton iterations and increments, where the time
// went (elements, assembly, linear solver), and an error against a stated reference:
//   indent       peak Fz vs the impenetrable limit 293.78 N (K_p = 1e7, docs/results/validation.md);
//   indent_line  peak Fz vs the same scene at 0.25 mm of travel per increment (637.72 N);
//   line_*, *_brick, *_solid_shell  none (reference_error printed as 0; half vs full, solids vs shells:
//                docs/results/validation.md, docs/design/numerics-solid.md).
// The line scenes are long (minutes): select them with --benchmark_filter.
#include "bench/bench_main.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/runtime/omp_wait_policy.hpp"
#include "bench/scene_runs.hpp"
#include "forward/scenes/forming/forming_run.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace spifit;

namespace {

struct Case {
  const char* name;
  const char* file;     // relative to the source tree
  double reference_fz;  // 0: no reference
  int repetitions;
};

const Case kCases[] = {
    {"indent", "experiments/aa3003o/scenes/indent.toml", 293.78, 5},
    {"indent_line", "experiments/aa3003o/scenes/indent_line.toml", 637.72, 3},
    {"indent_brick", "experiments/aa3003o/scenes/indent_brick.toml", 0.0, 3},
    {"indent_solid_shell", "experiments/aa3003o/scenes/indent_solid_shell.toml", 0.0, 3},
    {"line_half", "experiments/aa3003o/scenes/line_half.toml", 0.0, 1},
    {"line_half_brick", "experiments/aa3003o/scenes/line_half_brick.toml", 0.0, 1},
    {"line_half_solid_shell", "experiments/aa3003o/scenes/line_half_solid_shell.toml", 0.0, 1},
    {"line_full", "experiments/aa3003o/scenes/line_full.toml", 0.0, 1},
};

void forming_scene(benchmark::State& state, const Case& c) {
  const scene::FormingScene s = scene::read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/" + c.file);
  const bench::SceneRuns runs = bench::run_scene_repeatedly(state, c.name, [&](const scene::RunFiles& out) { return scene::run_forming_scene(s, out); });
  if (runs.walls.empty()) return;
  const nlohmann::json& last = runs.last;
  const std::size_t k = runs.walls.size();
  const double median = runs.median();
  const double fz = last["peak_force"][2].get<double>();
  state.counters["median_s"] = median;
  state.counters["min_s"] = runs.walls.front();
  state.counters["elements"] = last["model"]["elements"].get<double>();
  state.counters["increments"] = last["increments"].get<double>();
  state.counters["newton_its"] = last["newton_iterations"].get<double>();
  state.counters["peak_fz"] = fz;
  state.counters["ref_error"] = c.reference_fz > 0.0 ? fz / c.reference_fz - 1.0 : 0.0;
  state.counters["elements_s"] = last["profile_seconds"]["elements"].get<double>();
  state.counters["linear_s"] = last["profile_seconds"]["linear_solver"].get<double>();
  state.counters["threads"] = omp_get_max_threads();
  std::printf("# %-12s median %.3f s over %zu runs, %d increments, %d Newton iterations, peak Fz %.2f N%s\n", c.name, median, k,
              last["increments"].get<int>(), last["newton_iterations"].get<int>(), fz,
              c.reference_fz > 0.0 ? (" (" + std::to_string(100.0 * (fz / c.reference_fz - 1.0)) + " % vs reference)").c_str() : "");
}

}  // namespace

int main(int argc, char** argv) {
  runtime::ensure_passive_omp_wait(argv);  // as spifit itself
  for (const Case& c : kCases) {
    benchmark::RegisterBenchmark((std::string("forming/") + c.name).c_str(), forming_scene, c)
        ->Iterations(c.repetitions)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  }
  return spifit::bench::run_registered_benchmarks(argc, argv);
}
