#pragma once
// Helpers that let the templated constitutive code run with double or ceres::Jet.
#include <cmath>
#include <type_traits>

namespace spifit {

template <typename T>
inline double value_of(const T& x) {
  if constexpr (std::is_arithmetic_v<T>) {
    return static_cast<double>(x);
  } else {
    return value_of(x.a);  // ceres::Jet (possibly nested)
  }
}

template <typename T>
inline bool is_finite(const T& x) {
  return std::isfinite(value_of(x));
}

// psi(x) = (1 - exp(-x)) / x and its derivative, used by the exponential integration of
// the back-stress (return_mapping.hpp). psi via expm1 is accurate for every x != 0; psi'
// cancels for small x, so its Taylor series is used below |x| = 0.1 (error < 1e-12).
template <typename T>
inline T psi_exp(const T& x) {
  using std::expm1;
  if (value_of(x) == 0.0) return T(1.0) - x / 2.0;
  return -expm1(-x) / x;
}
template <typename T>
inline T psi_exp_derivative(const T& x) {
  using std::exp;
  if (std::abs(value_of(x)) < 0.1) {
    // sum_{k>=1} (-1)^k k x^(k-1) / (k+1)!
    return T(-0.5) + x * (1.0 / 3.0 + x * (-1.0 / 8.0 + x * (1.0 / 30.0 + x * (-1.0 / 144.0 + x * (1.0 / 840.0 + x * (-1.0 / 5760.0))))));
  }
  return (exp(-x) * (T(1.0) + x) - T(1.0)) / (x * x);
}

// x^p for x > 0: by repeated multiplication when p is a small whole number and T is double (the
// usual exponents of Yld2000-2d, 6 and 8, and their neighbours: ten times faster than std::pow,
// within a few ulps of it), by pow otherwise (Jets carry d/dp through pow).
template <typename T>
inline T real_power(const T& x, const T& p) {
  if constexpr (std::is_same_v<T, double>) {
    if (p == std::nearbyint(p) && std::abs(p) <= 64.0) {
      int n = static_cast<int>(std::abs(p));
      double base = x, r = 1.0;
      while (n > 0) {
        if (n & 1) r *= base;
        base *= base;
        n >>= 1;
      }
      return p < 0.0 ? 1.0 / r : r;
    }
  }
  using std::pow;
  return pow(x, p);
}

}  // namespace spifit
