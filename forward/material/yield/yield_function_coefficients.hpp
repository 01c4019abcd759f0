#pragma once
// The yield function of a card, held by MaterialParams whatever the function: -1 for Hill 1948
// (the quadratic default, coefficients F, G, H, L, M, N of MaterialParams, von Mises when all are
// their defaults), otherwise the function's index in the registry (yield_functions.hpp) and its
// coefficients in the order the function declares them. Templated on the scalar type (Jets).
#include "forward/material/law_coefficient.hpp"

#include <Eigen/Core>
#include <array>

namespace spifit::material {

inline constexpr int kMaxYieldCoefficients = 9;

template <typename T>
struct YieldFunction {
  int law = -1;  // index in YieldFunctionList; -1: Hill 1948 (quadratic)
  std::array<T, kMaxYieldCoefficients> c{};

  bool active() const { return law >= 0; }  // a registered (non-quadratic) function, not Hill
  T& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  const T& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
};

// The equivalent stress of a plane-stress shifted stress xi = (xx, yy, xy) (tensor shear), its
// gradient (the plastic strain rate per unit equivalent plastic strain rate, engineering shear)
// and its Hessian, and the exponent a for which sigma_eq^a is smooth (the return mapping
// iterates on sigma_eq^a, return_mapping.hpp).
template <typename T>
struct YieldValue {
  T value = T(0.0);
  T exponent = T(2.0);
  Eigen::Matrix<T, 3, 1> gradient = Eigen::Matrix<T, 3, 1>::Zero();
  Eigen::Matrix<T, 3, 3> hessian = Eigen::Matrix<T, 3, 3>::Zero();
};

}  // namespace spifit::material
