// Wall time of the bundled cone scenes (speed goals on 2 cores: cone70 fine mesh,
// 60 contours < 10 min; vwall on the 45-degree pie, 5 stages < 1 h; thesis: 101 h for vwall).
// Each benchmark runs the scene file as `spifit run` would (outputs to a temporary directory,
// removed afterwards) and prints the median wall time, Newton iterations, increments, cut-backs,
// completed contours, seconds per contour and where the time went (elements, assembly, linear
// solver). Error against a reference: the steady-state Fz is only defined for the 100-contour
// cone70 (docs/design/cone.md), so the line reports the last contour's central-third mean Fz
// for comparison by eye with the tables there (read from the run's contours.csv). Only
// cone70_short (3 contours, about a minute) runs by default: the others take minutes to hours
// and are selected with --benchmark_filter; --benchmark_filter=cone50_ runs the pie trade (the
// first 10 contours of cone50 on the 45, 90 and 360 degree meshes of one layout), and
// cone70_fine_loose_60 the 60 fine contours with loose Newton tolerances (the speed/accuracy
// trade of docs/results/benchmarks.md, "Looser Newton tolerances"), cone70_fine_floor_60 with a
// coarsened floor, cone70_fine_fast_60 with both.
// --benchmark_repetitions=N repeats a scene N times and adds Google Benchmark's median (the
// "_median" row) over the repetitions.
#include "bench/bench_main.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/runtime/omp_wait_policy.hpp"
#include "bench/scene_runs.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "inverse/experiments/measurement.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

using namespace spifit;

namespace {

struct Case {
  const char* name;
  const char* file;  // relative to the source tree
  int repetitions;
  bool by_default;
};

const Case kCases[] = {
    {"cone70_short", "experiments/aa3003o/scenes/cone70_pie45_short.toml", 1, true},
    {"cone50_pie45_10", "experiments/aa3003o/scenes/cone50_pie45_10.toml", 1, false},
    {"cone50_pie90_10", "experiments/aa3003o/scenes/cone50_pie90_10.toml", 1, false},
    {"cone50_disc360_10", "experiments/aa3003o/scenes/cone50_disc360_10.toml", 1, false},
    {"cone70_fine_60", "experiments/aa3003o/scenes/cone70_pie45_fine.toml", 1, false},
    {"cone70_fine_loose_60", "experiments/aa3003o/scenes/cone70_pie45_fine_loose.toml", 1, false},
    {"cone70_fine_floor_60", "experiments/aa3003o/scenes/cone70_pie45_fine_floor.toml", 1, false},
    {"cone70_fine_fast_60", "experiments/aa3003o/scenes/cone70_pie45_fine_fast.toml", 1, false},
    {"vwall_pie45", "experiments/aa3003o/scenes/vwall_pie45.toml", 1, false},
    {"vwall_pie45_polar", "experiments/aa3003o/scenes/vwall_pie45_polar.toml", 1, false},
};

// The last row of DIR/contours.csv (the central-third means of the last completed contour),
// read with the project's CSV reader; contour 0 if the file has no rows or cannot be read.
struct LastContour {
  int contour = 0;
  double fz = 0.0, fr = 0.0;
};
LastContour last_contour(const std::filesystem::path& csv) {
  LastContour out;
  try {
    const inverse::MeasurementTable t = inverse::read_measurement_csv(csv.string());
    if (t.rows() == 0) return out;
    const std::size_t last = t.rows() - 1;
    out = {static_cast<int>(t.column("contour")[last]), t.column("Fz")[last], t.column("Fr")[last]};
  } catch (const std::exception&) {
    // no contour to report
  }
  return out;
}

void cone_scene(benchmark::State& state, const Case& c) {
  const scene::ConeScene s = scene::read_cone_scene(std::string(SPIFIT_SOURCE_DIR) + "/" + c.file);
  LastContour lc;
  const bench::SceneRuns runs = bench::run_scene_repeatedly(state, c.name, [&](const scene::RunFiles& out) {
    auto report = scene::run_cone_scene(s, out);
    lc = last_contour(out.directory()->path() / "contours.csv");  // before the directory is removed
    return report;
  });
  if (runs.walls.empty()) return;
  const nlohmann::json& last = runs.last;
  const std::size_t k = runs.walls.size();
  const double median = runs.median();
  const int contours = last["contours_completed"].get<int>();
  state.counters["median_s"] = median;
  state.counters["elements"] = last["model"]["elements"].get<double>();
  state.counters["contours"] = contours;
  state.counters["s_per_contour"] = median / std::max(contours, 1);
  state.counters["increments"] = last["increments"].get<double>();
  state.counters["newton_its"] = last["newton_iterations"].get<double>();
  state.counters["cutbacks"] = last["cutbacks"].get<double>();
  state.counters["elements_s"] = last["profile_seconds"]["elements"].get<double>();
  state.counters["linear_s"] = last["profile_seconds"]["linear_solver"].get<double>();
  state.counters["threads"] = omp_get_max_threads();
  state.counters["last_Fz_N"] = lc.fz;
  std::printf("# %-16s median %.1f s over %zu run(s): %d elements, %d contours (%.1f s each), %d increments, %d Newton iterations, %d cut-backs;"
              " contour %d mean Fz %.1f N, Fr/Fz %.3f\n",
              c.name, median, k, last["model"]["elements"].get<int>(), contours, median / std::max(contours, 1),
              last["increments"].get<int>(), last["newton_iterations"].get<int>(), last["cutbacks"].get<int>(), lc.contour, lc.fz,
              lc.fz != 0.0 ? lc.fr / lc.fz : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  runtime::ensure_passive_omp_wait(argv);  // as spifit itself
  bool filtered = false;
  for (int i = 1; i < argc; ++i) filtered = filtered || std::string(argv[i]).rfind("--benchmark_filter", 0) == 0;
  for (const Case& c : kCases) {
    if (!c.by_default && !filtered) continue;
    benchmark::RegisterBenchmark((std::string("cone/") + c.name).c_str(), cone_scene, c)
        ->Iterations(c.repetitions)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  }
  return spifit::bench::run_registered_benchmarks(argc, argv);
}
