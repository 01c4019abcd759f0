// How right is the progress line's "about m:ss left" (cli/progress_meter.hpp)? Each benchmark runs
// a bundled FE scene as `spifit run` would (outputs to a temporary directory, removed afterwards),
// records the fraction of the tool path after every increment and the wall time since the run was
// started, and after the run compares what each estimator would have said when 10, 25, 50 and
// 75 % of the path were done with the time that was really left:
//   - recent: RemainingTime on the load factor (the path with the moves through the air shortened),
//     the rate over the last third of the time since the first increment, as the line says it;
//   - average: the share of the path done over the whole time so far (set-up included), as the
//     line said before.
// Counters: err_recent_NN and err_average_NN = (estimate - actual) / actual time left, at NN %.
// The indent scenes end before the line prints (3 s); line_half and the short cone by default.
#include "bench/bench_main.hpp"
#include "cli/progress_meter.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/runtime/omp_wait_policy.hpp"
#include "forward/scenes/scene_registry.hpp"

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace spifit;

namespace {

struct Case {
  const char* name;
  const char* file;  // relative to the source tree
};

const Case kCases[] = {
    {"line_half", "experiments/aa3003o/scenes/line_half.toml"},
    {"cone70_short", "experiments/aa3003o/scenes/cone70_pie45_short.toml"},
    {"cone50_pie45_10", "experiments/aa3003o/scenes/cone50_pie45_10.toml"},
};

constexpr double kAt[] = {0.10, 0.25, 0.50, 0.75};

void eta_accuracy(benchmark::State& state, const Case& c) {
  namespace fs = std::filesystem;
  const auto scene = scene::read_scene(std::string(SPIFIT_SOURCE_DIR) + "/" + c.file);
  const fs::path out = fs::temp_directory_path() / ("spifit_bench_eta_" + std::to_string(::getpid()));
  for (auto _ : state) {
    fs::remove_all(out);
    const auto dir = io::OutputDirectory::prepare(out.string(), false);
    struct Sample {
      double t, fraction, load;  // seconds since the start, share of the path, load factor
    };
    std::vector<Sample> samples;
    scene::RunControl control;
    const auto t0 = std::chrono::steady_clock::now();
    control.progress = [&](const scene::ProgressEvent& e) {
      samples.push_back({std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), e.fraction, e.load});
    };
    const auto result = scene->run(scene::RunFiles(dir), control);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!result->ok()) {
      state.SkipWithError(result->message.c_str());
      break;
    }
    state.counters["total_s"] = total;
    std::string line;
    for (double at : kAt) {
      cli::RemainingTime recent;
      double elapsed = 0.0, fraction = 0.0;
      for (const Sample& x : samples) {
        recent.add(x.load, x.t);
        elapsed = x.t;
        fraction = x.fraction;
        if (x.fraction >= at) break;
      }
      const double actual = total - elapsed;
      const double average = elapsed * (1.0 - fraction) / fraction;
      const int pct = static_cast<int>(at * 100.0 + 0.5);
      char key[32];
      if (const auto left = recent.seconds()) {
        std::snprintf(key, sizeof key, "err_recent_%02d", pct);
        state.counters[key] = (*left - actual) / actual;
      }
      std::snprintf(key, sizeof key, "err_average_%02d", pct);
      state.counters[key] = (average - actual) / actual;
      char buf[160];
      std::snprintf(buf, sizeof buf, " %d%%: left %.1f s, recent %.1f s, average %.1f s;", pct, actual,
                    recent.seconds() ? *recent.seconds() : -1.0, average);
      line += buf;
    }
    std::printf("%s: %.1f s in all;%s\n", c.name, total, line.c_str());
  }
  fs::remove_all(out);
}

}  // namespace

int main(int argc, char** argv) {
  runtime::ensure_passive_omp_wait(argv);
  for (const Case& c : kCases)
    benchmark::RegisterBenchmark((std::string("eta/") + c.name).c_str(), [&c](benchmark::State& s) { eta_accuracy(s, c); })
        ->Iterations(1)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  return bench::run_registered_benchmarks(argc, argv);
}
