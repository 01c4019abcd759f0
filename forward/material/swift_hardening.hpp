#pragma once
// Swift isotropic hardening (thesis eq. 3.7): sigma_F(p) = K (eps0 + p)^n.
// n = 0 gives perfect plasticity at sigma_F = K.
#include "forward/material/material_params.hpp"

#include <cmath>

namespace spifit::material {

template <typename T>
inline T swift_yield_stress(const MaterialParams<T>& m, const T& p) {
  using std::pow;
  return m.K * pow(m.eps0 + p, m.n);
}

template <typename T>
inline T swift_slope(const MaterialParams<T>& m, const T& p) {
  using std::pow;
  return m.n * m.K * pow(m.eps0 + p, m.n - 1.0);
}

}  // namespace spifit::material
