// The speed-accuracy trade of the explicit scheme (docs/results/benchmarks.md, "Explicit
// scheme"): the §7.1 indent and the half line test run explicitly over mass scalings, with the
// penalty and the Moving Spherical Tool contact, against the implicit run of the same scene
// (run once per scene). Each case prints and reports: wall time, steps, the peak-Fz error and
// the mean-|F| error over the path (forces compared at the same travel), the largest change of
// the last section's z (mm; line test: section E), the largest kinetic over internal energy once
// the internal energy has reached a tenth of its final value, and the relative energy-balance
// error at the end. Cases ending in /bulk_viscosity add the membrane's bulk viscosity; cases
// ending in /one_point_0.003 (or 0.01) integrate each element at its centre with that hourglass
// stiffness.
// Long: select cases with --benchmark_filter (e.g. explicit/indent or explicit/line_half/.*/1e6).
#include "bench/bench_main.hpp"
#include "forward/runtime/omp_wait_policy.hpp"
#include "forward/scenes/forming/forming_run.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace spifit;

namespace {

struct Case {
  std::string scene;   // file name under experiments/aa3003o/scenes
  bool mst = false;
  double mass_scaling = 1.0;
  double time_scaling = 1.0;
  bool bulk_viscosity = false;  // b1 = 0.06, b2 = 1.2 (the defaults of Abaqus/Explicit)
  double hourglass = 0.0;        // > 0: the one-point element with this hourglass stiffness
};

scene::FormingScene read(const std::string& file) {
  return scene::read_forming_scene(std::string(SPIFIT_SOURCE_DIR) + "/experiments/aa3003o/scenes/" + file);
}

const scene::FormingResult& implicit_reference(const std::string& file) {
  static std::map<std::string, scene::FormingResult> cache;
  auto it = cache.find(file);
  if (it == cache.end()) it = cache.emplace(file, scene::run_forming_scene(read(file))).first;
  return it->second;
}

// |F| of a history at a travel (linear between samples).
double force_at(const std::vector<scene::ToolForceSample>& h, double travel) {
  auto it = std::lower_bound(h.begin(), h.end(), travel, [](const scene::ToolForceSample& s, double t) { return s.travel < t; });
  if (it == h.begin()) return it->force.norm();
  if (it == h.end()) return h.back().force.norm();
  const auto& a = *(it - 1);
  const auto& b = *it;
  const double w = (travel - a.travel) / (b.travel - a.travel);
  return (1.0 - w) * a.force.norm() + w * b.force.norm();
}

// Largest |z| difference of the last section, the explicit one read at the reference's x0.
double section_change(const scene::FormingResult& ref, const scene::FormingResult& r) {
  if (ref.sections.empty() || r.sections.empty()) return 0.0;
  const io::Series& a = ref.sections.back().nodes;
  const io::Series& b = r.sections.back().nodes;
  const auto xa = a.column("x0"), za = a.column("z"), xb = b.column("x0"), zb = b.column("z");
  double worst = 0.0;
  for (std::size_t i = 0; i < xa.size() && i < xb.size(); ++i)
    if (std::abs(xa[i] - xb[i]) < 1e-9) worst = std::max(worst, std::abs(za[i] - zb[i]));
  return worst;
}

void explicit_case(benchmark::State& state, const Case& c) {
  const scene::FormingResult& ref = implicit_reference(c.scene);
  scene::FormingScene s = read(c.scene);
  s.explicit_scheme = true;
  s.explicit_options.mass_scaling = c.mass_scaling;
  s.explicit_options.time_scaling = c.time_scaling;
  if (c.mst) s.contact.method = contact::ContactOptions::Method::mst;
  if (c.bulk_viscosity) {
    s.explicit_options.bulk_viscosity_linear = 0.06;
    s.explicit_options.bulk_viscosity_quadratic = 1.2;
  }
  s.hourglass_stiffness = c.hourglass;
  scene::FormingResult r;
  for (auto _ : state) r = scene::run_forming_scene(s);
  if (!r.ok()) {
    state.SkipWithError(("run failed: " + r.message).c_str());
    return;
  }
  const auto& h = r.force.samples();
  const auto& hr = ref.force.samples();
  double mean = 0.0, mean_ref = 0.0;
  for (const auto& x : hr) {
    mean_ref += x.force.norm();
    mean += force_at(h, x.travel);
  }
  const double mean_error = mean / mean_ref - 1.0;
  const double peak_error = r.force.peak().z() / ref.force.peak().z() - 1.0;
  const nlohmann::json j = r.to_json();
  const double ratio = j["explicit"]["max_kinetic_over_internal"].get<double>();
  const double steps = j["explicit"]["steps"].get<double>();
  const double balance = j["energies"]["relative_balance_error"].get<double>();
  const double dz = section_change(ref, r);
  state.counters["wall_s"] = r.wall_seconds;
  state.counters["implicit_s"] = ref.wall_seconds;
  state.counters["steps"] = steps;
  state.counters["peak_fz_error"] = peak_error;
  state.counters["mean_force_error"] = mean_error;
  state.counters["section_dz_mm"] = dz;
  state.counters["kinetic_ratio"] = ratio;
  state.counters["balance_error"] = balance;
  state.counters["threads"] = omp_get_max_threads();
  std::printf("# %s %s%s hourglass %g mass_scaling %.0e time_scaling %g: %.1f s (implicit %.1f s), %.0f steps, peak Fz %+.2f %%, mean |F| %+.2f %%, section %.3f mm, "
              "kinetic/internal %.3g, balance %.2g\n",
              c.scene.c_str(), c.mst ? "mst" : "penalty", c.bulk_viscosity ? " bulk_viscosity" : "", c.hourglass, c.mass_scaling, c.time_scaling, r.wall_seconds, ref.wall_seconds, steps, 100.0 * peak_error,
              100.0 * mean_error, dz, ratio, balance);
}

}  // namespace

int main(int argc, char** argv) {
  runtime::ensure_passive_omp_wait(argv);  // as spifit itself
  std::vector<Case> cases;
  for (bool mst : {false, true}) {
    for (double m : {1e2, 1e3, 1e4, 1e5, 1e6}) cases.push_back({"indent.toml", mst, m});
    for (double m : {1e4, 1e5, 1e6, 1e7}) cases.push_back({"line_half.toml", mst, m});
  }
  // Time scaling trades as mass scaling: inertia grows with (time scaling)^2 x mass scaling, the
  // steps fall with time scaling x its square root.
  cases.push_back({"indent.toml", false, 1e4, 10.0});
  cases.push_back({"line_half.toml", false, 1e4, 10.0});
  // Bulk viscosity against the ringing of the membrane.
  for (double m : {1e5, 1e6}) cases.push_back({"indent.toml", false, m, 1.0, true});
  for (double m : {1e5, 1e6, 1e7}) cases.push_back({"line_half.toml", false, m, 1.0, true});
  // The one-point element: a quarter of the material updates.
  for (double hg : {0.003, 0.01})
    for (bool mst : {false, true}) {
      for (double m : {1e4, 1e5, 1e6}) cases.push_back({"indent.toml", mst, m, 1.0, false, hg});
      for (double m : {1e5, 1e6}) cases.push_back({"line_half.toml", mst, m, 1.0, false, hg});
    }
  for (const Case& c : cases) {
    char name[160], one_point[32] = "";
    if (c.hourglass > 0.0) std::snprintf(one_point, sizeof one_point, "/one_point_%g", c.hourglass);
    std::snprintf(name, sizeof name, "explicit/%s/%s/%.0e%s%s%s", c.scene.substr(0, c.scene.find('.')).c_str(), c.mst ? "mst" : "penalty",
                  c.mass_scaling, c.time_scaling != 1.0 ? "/time_scaling_10" : "", c.bulk_viscosity ? "/bulk_viscosity" : "", one_point);
    benchmark::RegisterBenchmark(name, explicit_case, c)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
  }
  return spifit::bench::run_registered_benchmarks(argc, argv);
}
