// Time of one 200-increment tensile curve (goal < 1 ms, docs/results/benchmarks.md,
// "Material points and fit_classic") and its error against the closed-form Hill 1948 + Swift
// solution, printed as counters.
#include "forward/material/hill48.hpp"
#include "forward/material/material_card.hpp"
#include "forward/material/yield/yield_functions.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/closed_form.hpp"  // closed forms shared with the tests

#include <benchmark/benchmark.h>

#include <numbers>

using namespace spifit;

namespace {

material::MaterialCard load(const char* name) {
  if (std::string(name) == "yld2000_fitted") {  // fit_yld2000's card: Yld2000-2d, a = 8, Swift of C.4
    auto c = load("aa3003o_yld2000_start");
    c.params.yield = material::make_yield_function<material::Yld2000_2d>({1.0102, 0.90871, 1.0, 1.0, 1.0151, 1.0, 1.0906, 1.4135, 8.0});
    return c;
  }
  return material::load_material_card(std::string(SPIFIT_SOURCE_DIR) + "/materials/" + name + ".toml");
}

void tensile_curve(benchmark::State& state, const char* card_name, double angle) {
  const auto card = load(card_name);
  scene::MaterialPointSetup s;
  s.kind = scene::MaterialPointKind::tensile;
  s.angle_deg = angle;
  s.strain_path = {0.3};
  s.increments = 200;
  scene::MaterialPointResult<double> r;
  for (auto _ : state) {
    r = scene::run_material_point(card.params, s);
    benchmark::DoNotOptimize(r.curve.data());
  }
  double err = 0.0;
  if (!card.params.kinematic.active()) {
    const double a = angle * std::numbers::pi / 180.0;
    const double factor = card.params.yield.active() ? material::uniaxial_yield_factor(card.params, a) : material::uniaxial_stress_factor(card.hill(), a);
    const test::UniaxialClosedForm cf{card.params, factor};
    for (const auto& p : r.curve) {
      if (p.control_strain > 0) err = std::max(err, std::abs(p.stress_kirchhoff / cf.stress(p.control_strain) - 1.0));
    }
    state.counters["max_rel_error"] = err;
  }
  state.counters["substeps"] = r.substeps;
  state.counters["newton_iters"] = r.newton_iterations;
}

}  // namespace

BENCHMARK_CAPTURE(tensile_curve, c3c4_00deg, "aa3003o_c3c4", 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tensile_curve, c3c4_45deg, "aa3003o_c3c4", 45.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tensile_curve, c7_af_45deg, "aa3003o_c7_af_shell", 45.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tensile_curve, c8_ziegler_00deg, "aa3003o_c8_ziegler_shell", 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tensile_curve, yld2000_a8_00deg, "yld2000_fitted", 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tensile_curve, yld2000_a8_45deg, "yld2000_fitted", 45.0)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();

// Speed/accuracy trade of the kinematic sub-step bound (DriverOptions::kinematic_substep):
// card C.7 (Hill + Armstrong-Frederick, no closed form), tension to 0.3 then back to 0.15 at
// 45 deg, 180 increments; error = max |stress - reference| / max |reference| where the
// reference is the same law with 20x the increments and kinematic_substep = 1e-4.
// Argument = kinematic_substep x 1000.
static void kinematic_substep_trade(benchmark::State& state) {
  static const auto card = load("aa3003o_c7_af_shell");
  scene::MaterialPointSetup s;
  s.kind = scene::MaterialPointKind::tensile;
  s.angle_deg = 45.0;
  s.strain_path = {0.3, 0.15};
  s.increments = 180;
  static const auto reference = [] {
    scene::MaterialPointSetup f;
    f.kind = scene::MaterialPointKind::tensile;
    f.angle_deg = 45.0;
    f.strain_path = {0.3, 0.15};
    f.increments = 180 * 20;
    f.driver.kinematic_substep = 1e-4;
    return scene::run_material_point(card.params, f);
  }();
  s.driver.kinematic_substep = static_cast<double>(state.range(0)) / 1000.0;
  scene::MaterialPointResult<double> r;
  for (auto _ : state) {
    r = scene::run_material_point(card.params, s);
    benchmark::DoNotOptimize(r.curve.data());
  }
  double scale = 0.0, err = 0.0;
  for (const auto& p : reference.curve) scale = std::max(scale, std::abs(p.stress));
  for (std::size_t i = 0; i < r.curve.size(); ++i) err = std::max(err, std::abs(r.curve[i].stress - reference.curve[20 * i].stress));
  state.counters["max_rel_error"] = err / scale;
  state.counters["substeps"] = r.substeps;
}
BENCHMARK(kinematic_substep_trade)->Arg(0)->Arg(200)->Arg(50)->Arg(20)->Arg(5)->Unit(benchmark::kMicrosecond);
