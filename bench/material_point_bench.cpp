// Time of one 200-increment tensile curve (SPEC §8 goal: < 1 ms) and its error against the
// closed-form Hill 1948 + Swift solution, printed as counters.
#include "forward/material/hill48.hpp"
#include "forward/material/material_card.hpp"
#include "forward/scenes/material_point_test.hpp"

#include <benchmark/benchmark.h>

#include <numbers>

using namespace spifit;

namespace {

material::MaterialCard load(const char* name) {
  return material::load_material_card(std::string(SPIFIT_SOURCE_DIR) + "/materials/" + name + ".toml");
}

// Closed-form Kirchhoff stress of a Hill + Swift uniaxial test at total strain eps.
double closed_form(const material::MaterialParams<double>& m, double h, double eps) {
  if (eps * m.E <= material::swift_yield_stress(m, 0.0) / h) return eps * m.E;
  double lo = 0.0, hi = eps / h;
  for (int i = 0; i < 200; ++i) {
    const double p = 0.5 * (lo + hi);
    (material::swift_yield_stress(m, p) / h / m.E + h * p < eps ? lo : hi) = p;
  }
  return material::swift_yield_stress(m, 0.5 * (lo + hi)) / h;
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
  if (card.params.kinematic == material::KinematicLaw::none) {
    const double h = material::uniaxial_stress_factor(card.hill(), angle * std::numbers::pi / 180.0);
    for (const auto& p : r.curve) {
      if (p.control_strain > 0) err = std::max(err, std::abs(p.stress_kirchhoff / closed_form(card.params, h, p.control_strain) - 1.0));
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

BENCHMARK_MAIN();
