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

// psi(x) = (1 - exp(-x)) / x and its derivative, accurate near x = 0 (series below 1e-3).
// Used by the exponential integration of the back-stress (return_mapping.hpp).
template <typename T>
inline T psi_exp(const T& x) {
  using std::exp;
  if (std::abs(value_of(x)) < 1e-3) return T(1.0) - x / 2.0 + x * x / 6.0 - x * x * x / 24.0 + x * x * x * x / 120.0;
  return (T(1.0) - exp(-x)) / x;
}
template <typename T>
inline T psi_exp_derivative(const T& x) {
  using std::exp;
  if (std::abs(value_of(x)) < 1e-3) return T(-0.5) + x / 3.0 - x * x / 8.0 + x * x * x / 30.0;
  return (exp(-x) * (T(1.0) + x) - T(1.0)) / (x * x);
}

}  // namespace spifit
