#pragma once
// Shared by the scene benchmarks (bench_forming, bench_cone): run a scene once per benchmark
// iteration into a temporary output directory (removed afterwards) and collect the wall times
// from its summary.json. A failed run stops the benchmark with the run's message.
#include "forward/io/output_directory.hpp"
#include "forward/scenes/common/run_files.hpp"

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace spifit::bench {

struct SceneRuns {
  std::vector<double> walls;  // sorted
  nlohmann::json last;        // summary of the last run
  double median() const {
    const std::size_t k = walls.size();
    return k % 2 ? walls[k / 2] : 0.5 * (walls[k / 2 - 1] + walls[k / 2]);
  }
};

// run(files) returns the scene's typed result (a scene::SceneResult).
template <typename Run>
SceneRuns run_scene_repeatedly(benchmark::State& state, const std::string& name, Run run) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("spifit_bench_" + name + "_" + std::to_string(::getpid()));
  SceneRuns r;
  for (auto _ : state) {
    const auto out = io::OutputDirectory::prepare(dir.string(), true);
    const auto rep = run(scene::RunFiles(out));
    if (!rep.ok()) {
      state.SkipWithError(("run failed: " + rep.message).c_str());
      break;
    }
    r.walls.push_back(rep.wall_seconds);
    r.last = rep.to_json();
  }
  std::filesystem::remove_all(dir);
  std::sort(r.walls.begin(), r.walls.end());
  return r;
}

}  // namespace spifit::bench
