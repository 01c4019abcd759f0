#pragma once
// The element sensitivity tests' parameters: Swift's K and n, the Armstrong-Frederick C_X and
// Young's modulus in slots 0 to 3, Poisson's ratio in slot 5; slot 4 is left to a parameter the
// nodes' path depends on.
#include "forward/material/material_params.hpp"
#include "forward/material/sensitivity_scalar.hpp"

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

}  // namespace spifit::test
