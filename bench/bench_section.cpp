// Cost of one layer-point update of the shell section (log strain, return mapping, the
// section's sums), the kernel inside every element evaluation. One core, no element, no
// assembly: the number is core time per layer point, comparable across machines and builds.
//
// Path: a section of card C.3 + C.4, t = 1.2 mm, 5 Gauss points, taken through 200 increments
// of a tool passing over it (strains_at): the layers flex elastically, load, yield, unload,
// reverse and flex elastically again. About a third of the layer updates are plastic, as in the
// line test, where 22-47 % of the sections are plastic at any evaluation. Each increment has
// three trial updates (at 0.9, 0.99 and 1.0 of its strain, as Newton iterates approach the end)
// and a commit.
// Modes: tangent (an implicit iteration), residual (the final iterate without the element
// tangent: the layers still keep their consistent tangents) and explicit (no layer tangents).
// Counters: per_layer_point (time per layer-point update, printed with an SI prefix: 400n =
// 400 ns) and plastic_share (the share of layer updates that returned to the yield surface).
#include "bench/bench_main.hpp"
#include "forward/element/shell_section.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

using namespace spifit;

namespace {

constexpr int kIncrements = 200;
constexpr double kBend = 0.03;  // curvature amplitude [1/mm]
constexpr double kIterateFractions[] = {0.9, 0.99, 1.0};

material::MaterialParams<double> card_c3_c4() {
  material::MaterialParams<double> p;  // E, nu, Swift: card C.4 = defaults
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;  // card C.3
  return p;
}

// The tool passes over the section in the middle third of the path: the membrane strain rises
// to (0.03, 0.012, 0.006) and the curvature swings once through +-kBend; before and after, a
// small elastic flexing of the far field (1e-4 1/mm).
void strains_at(double k, element::Vec3* e, element::Vec3* kappa) {
  const double s = k / kIncrements;
  const double u = std::clamp(3.0 * s - 1.0, 0.0, 1.0);  // 0 before the tool, 1 after it
  const double ramp = u * u * (3.0 - 2.0 * u);
  const double swing = std::sin(2.0 * M_PI * u);
  const double far = 1e-4 * std::sin(8.0 * M_PI * s);
  *e = ramp * element::Vec3(0.03, 0.012, 0.006);
  *kappa = element::Vec3(kBend * swing + far, 0.3 * kBend * swing - far, 0.2 * kBend * swing);
}

enum class Mode { tangent, residual, explicit_step };

void BM_SectionUpdate(benchmark::State& state) {
  const Mode mode = static_cast<Mode>(state.range(0));
  const material::ReturnMapping<double, 3> law(card_c3_c4());
  const element::ThicknessRule rule = element::gauss_legendre_rule(5);
  std::int64_t updates = 0, plastic = 0;
  for (auto _ : state) {
    element::ShellSection section(law, rule, 1.2);
    section.set_layer_tangents(mode != Mode::explicit_step);
    element::Vec6 resultant;
    element::Mat6 tangent;
    element::Vec3 e0, k0, e1, k1;
    strains_at(0.0, &e0, &k0);
    for (int inc = 1; inc <= kIncrements; ++inc) {
      strains_at(inc, &e1, &k1);
      for (double f : kIterateFractions) {
        const element::Vec3 e = e0 + f * (e1 - e0), kappa = k0 + f * (k1 - k0);
        const auto st = section.update(e, kappa, &resultant, mode == Mode::tangent ? &tangent : nullptr);
        if (!st.ok) {
          state.SkipWithError(st.reason.c_str());
          return;
        }
        for (int l = 0; l < section.layers(); ++l)
          plastic += section.layer_trial_state(l).eqps > section.layer_state(l).eqps ? 1 : 0;
        updates += section.layers();
      }
      benchmark::DoNotOptimize(resultant.data());
      benchmark::DoNotOptimize(tangent.data());
      section.commit();
      e0 = e1;
      k0 = k1;
    }
  }
  // Seconds per layer-point update (printed with an SI prefix: 400n = 400 ns).
  state.counters["per_layer_point"] =
      benchmark::Counter(static_cast<double>(updates), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["plastic_share"] = static_cast<double>(plastic) / static_cast<double>(updates);
}

}  // namespace

BENCHMARK(BM_SectionUpdate)->Arg(static_cast<int>(Mode::tangent))->ArgName("tangent");
BENCHMARK(BM_SectionUpdate)->Arg(static_cast<int>(Mode::residual))->ArgName("residual");
BENCHMARK(BM_SectionUpdate)->Arg(static_cast<int>(Mode::explicit_step))->ArgName("explicit");

int main(int argc, char** argv) { return spifit::bench::run_registered_benchmarks(argc, argv); }
