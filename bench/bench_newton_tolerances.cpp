// The speed-accuracy trade of the Newton settings of the forming scenes: each setting's wall
// time (median of the repetitions), Newton iterations, and its error against the same scene
// with the bundled settings ("today's results"):
//   force_err    largest |F(travel) - F_bundled(travel)| over the path, any component, over the
//                largest bundled |F| (linear interpolation in travel between increments);
//   section_um   largest |z - z_bundled| of the sections' nodes [micrometres].
// The bundled settings themselves are compared with a tight run (1e-7 on both tests), which
// says how far today's results are from converged. Select a scene with --benchmark_filter
// (line_half takes about 40 s a run, so a full study is several minutes).
#include "bench/bench_main.hpp"
#include "bench/scene_runs.hpp"
#include "forward/runtime/omp_wait_policy.hpp"
#include "forward/scenes/forming/forming_run.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace spifit;

namespace {

struct Setting {
  const char* name;
  double force_tolerance, displacement_tolerance;  // 0: the scene's
  bool estimate_next_correction;
  double travel_scale;  // x the scene's travel_per_increment
};

const Setting kSettings[] = {
    {"bundled", 0.0, 0.0, false, 1.0},
    {"tight_1e-7", 1e-7, 1e-7, false, 1.0},
    {"bundled_estimate", 0.0, 0.0, true, 1.0},
    {"1e-4_1e-3_estimate", 1e-4, 1e-3, true, 1.0},
    {"1e-3_1e-3_estimate", 1e-3, 1e-3, true, 1.0},
    {"5e-3_1e-2_estimate", 5e-3, 1e-2, true, 1.0},
    {"1e-3_1e-3_estimate_travel_x2", 1e-3, 1e-3, true, 2.0},
};

const char* const kScenes[] = {"indent_line", "line_half"};

// The bundled run of each scene, the reference of the others.
std::map<std::string, scene::FormingResult>& bundled_runs() {
  static std::map<std::string, scene::FormingResult> runs;
  return runs;
}

scene::FormingScene scene_with(const std::string& name, const Setting& s) {
  scene::FormingScene sc = scene::read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/" + name + ".toml");
  if (s.force_tolerance > 0.0) sc.force_tolerance = s.force_tolerance;
  if (s.displacement_tolerance > 0.0) sc.displacement_tolerance = s.displacement_tolerance;
  sc.estimate_next_correction = s.estimate_next_correction;
  sc.travel_per_increment *= s.travel_scale;
  return sc;
}

// Largest force difference over the reference's largest force magnitude.
double force_error(const scene::ToolForceHistory& a, const scene::ToolForceHistory& ref) {
  const auto& r = ref.samples();
  const auto& s = a.samples();
  double scale = 0.0, worst = 0.0;
  for (const auto& p : r) scale = std::max(scale, p.force.cwiseAbs().maxCoeff());
  std::size_t j = 0;
  for (const auto& p : r) {
    while (j + 1 < s.size() && s[j + 1].travel < p.travel) ++j;
    if (s.empty() || p.travel < s.front().travel || p.travel > s.back().travel) continue;
    Eigen::Vector3d f = s[j].force;
    if (j + 1 < s.size() && s[j + 1].travel > s[j].travel) {
      const double w = std::clamp((p.travel - s[j].travel) / (s[j + 1].travel - s[j].travel), 0.0, 1.0);
      f = (1.0 - w) * s[j].force + w * s[j + 1].force;
    }
    worst = std::max(worst, (f - p.force).cwiseAbs().maxCoeff());
  }
  return scale > 0.0 ? worst / scale : 0.0;
}

// Largest difference of the sections' z between runs of the same mesh [mm].
double section_error(const scene::FormingResult& a, const scene::FormingResult& ref) {
  double worst = 0.0;
  for (std::size_t k = 0; k < std::min(a.sections.size(), ref.sections.size()); ++k) {
    const std::vector<double> z = a.sections[k].nodes.column("z"), zr = ref.sections[k].nodes.column("z");
    for (std::size_t i = 0; i < std::min(z.size(), zr.size()); ++i) worst = std::max(worst, std::abs(z[i] - zr[i]));
  }
  return worst;
}

void tolerance_setting(benchmark::State& state, const std::string& name, const Setting& setting) {
  const scene::FormingScene sc = scene_with(name, setting);
  scene::FormingResult last;
  const bench::SceneRuns runs = bench::run_scene_repeatedly(state, name + "_" + setting.name, [&](const scene::RunFiles& out) {
    last = scene::run_forming_scene(sc, out);
    return last;
  });
  if (runs.walls.empty()) return;
  auto& bundled = bundled_runs();
  const bool is_bundled = std::string(setting.name) == "bundled";
  if (is_bundled) bundled[name] = last;
  const auto ref = bundled.find(name);
  double f_err = -1.0, s_err = -1.0;
  if (!is_bundled && ref != bundled.end()) {
    f_err = force_error(last.force, ref->second.force);
    s_err = section_error(last, ref->second);
  }
  state.counters["median_s"] = runs.median();
  state.counters["newton_its"] = runs.last["newton_iterations"].get<double>();
  state.counters["force_err"] = f_err;
  state.counters["section_um"] = s_err >= 0.0 ? 1e3 * s_err : -1.0;
  char errors[96] = " (the reference)";
  if (!is_bundled && last.sections.empty()) std::snprintf(errors, sizeof errors, ", force error %.2e", f_err);
  else if (!is_bundled) std::snprintf(errors, sizeof errors, ", force error %.2e, section error %.2f um", f_err, 1e3 * s_err);
  std::printf("# %-12s %-28s median %7.2f s over %zu runs, %5d iterations, %4d increments%s\n", name.c_str(), setting.name, runs.median(),
              runs.walls.size(), runs.last["newton_iterations"].get<int>(), runs.last["increments"].get<int>(), errors);
  if (std::string(setting.name) == "tight_1e-7" && ref != bundled.end())
    std::printf("#   (the bundled settings against this tight run: force error %.2e, section error %.2f um)\n",
                force_error(ref->second.force, last.force), 1e3 * section_error(ref->second, last));
}

}  // namespace

int main(int argc, char** argv) {
  runtime::ensure_passive_omp_wait(argv);  // as spifit itself
  for (const char* name : kScenes)
    for (const Setting& s : kSettings)
      benchmark::RegisterBenchmark((std::string("tolerances/") + name + "/" + s.name).c_str(), tolerance_setting, std::string(name), s)
          ->Iterations(3)
          ->Unit(benchmark::kSecond)
          ->UseRealTime();
  return spifit::bench::run_registered_benchmarks(argc, argv);
}
