#pragma once
// The element sensitivity tests' parameters (Swift's K and n, the Armstrong-Frederick C_X and
// Young's modulus in slots 0 to 3, Poisson's ratio in slot 5; slot 4 is left to a parameter the
// nodes' path depends on), and their comparison with central differences along the path.
#include "forward/material/material_params.hpp"
#include "forward/material/sensitivity_scalar.hpp"
#include "tests/support/central_differences.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace spifit::test {

inline material::SensitivityRow unit_row(int k) {
  material::SensitivityRow r = material::SensitivityRow::Zero();
  r(k) = 1.0;
  return r;
}

inline std::vector<material::FieldSeed> path_seeds(const material::MaterialParams<double>& p) {
  using material::MaterialField;
  return {{{MaterialField::hardening, p.hardening.law, 0}, unit_row(0)},
          {{MaterialField::hardening, p.hardening.law, 2}, unit_row(1)},
          {{MaterialField::kinematic, p.kinematic.law, 0}, unit_row(2)},
          {{MaterialField::E, -1, 0}, unit_row(3)},
          {{MaterialField::nu, -1, 0}, unit_row(5)}};
}

// Each slot's exact derivatives along a path (ddm[n].col(k) at increment n) against central
// differences of whole paths, steps h and h/4: run(params, s) gives the path's vectors with the
// card's parameters and the path parameter s (slot 4), view(n, v) what of a difference is compared.
template <class Vec, class Matrix, class Run, class View>
void expect_path_slots_match(const material::MaterialParams<double>& p, const std::vector<Matrix>& ddm, int slots, Run run, View view) {
  const std::vector<material::FieldSeed> sd = path_seeds(p);
  for (int k = 0; k < slots; ++k) {
    const double h = k == 0 ? 0.5 : k == 1 ? 1e-4 : k == 2 ? 0.05 : k == 3 ? 50.0 : k == 4 ? 1e-5 : 1e-4;
    std::vector<Vec> cd(ddm.size()), cd4(ddm.size());
    for (double step : {h, h / 4.0}) {
      material::MaterialParams<double> pp = p, pm = p;
      double sp = 0.0, sm = 0.0;
      if (k != 4) {
        const std::size_t seed = static_cast<std::size_t>(k < 4 ? k : 4);
        material::material_field(pp, sd[seed].field) += step;
        material::material_field(pm, sd[seed].field) -= step;
      } else {
        sp = step;
        sm = -step;
      }
      const std::vector<Vec> vp = run(pp, sp), vm = run(pm, sm);
      for (std::size_t n = 0; n < vp.size(); ++n) (step == h ? cd : cd4)[n] = view(n, Vec((vp[n] - vm[n]) / (2.0 * step)));
    }
    std::vector<Vec> exact;
    for (const auto& d : ddm) exact.push_back(d.col(k));
    const double worst = expect_within_central_differences(exact, cd, cd4, 1e-7, "slot " + std::to_string(k));
    std::printf("slot %d: largest relative difference to central differences (h/4) %.2e\n", k, worst);
  }
}

}  // namespace spifit::test
