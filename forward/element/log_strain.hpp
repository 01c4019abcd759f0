#pragma once
// In-plane logarithmic (Hencky) strain of a shell layer and its first and second derivatives
// with respect to the Green-Lagrange strain (docs/design/numerics-shell.md).
//
// The layer's in-plane right Cauchy-Green tensor in the material frame is C = I + 2E. For a
// symmetric 2x2 tensor every isotropic function is a I + b C; for the logarithm, with
// m = tr C / 2, det = det C and x^2 = 1 - det / m^2 (x = (l1 - l2) / (l1 + l2) for the
// eigenvalues l1, l2 of C):
//   ln C = a I + b C,  b = atanh(x) / (x m),  a = ln(det) / 2 - b m.
// atanh(x)/x depends on x^2 only, so a and b are smooth at equal eigenvalues (series there):
// no eigenvectors, no special cases. The derivatives follow in closed form by the chain rule
// through (m, det) (log_strain.cpp); the template below also runs on nested Jets, which the
// tests use as the reference.
// Vectors use engineering shear: E = (E11, E22, 2 E12), eps = (e11, e22, 2 e12).
#include "forward/material/scalar.hpp"

#include <Eigen/Core>

#include <array>
#include <type_traits>

namespace spifit::element {

// A constant of scalar type T (nested Jets need one explicit conversion per level).
template <typename T>
T lift(double v) {
  if constexpr (std::is_arithmetic_v<T>) return v;
  else return T(lift<typename T::Scalar>(v));
}

// eps(E) for any scalar type (double or ceres::Jet, possibly nested).
template <typename T>
Eigen::Matrix<T, 3, 1> log_strain_of_green(const Eigen::Matrix<T, 3, 1>& green) {
  using std::log;
  using std::sqrt;
  const T one = lift<T>(1.0), two = lift<T>(2.0), half = lift<T>(0.5);
  const T c11 = one + two * green(0), c22 = one + two * green(1), c12 = green(2);
  const T m = half * (c11 + c22);
  const T det = c11 * c22 - c12 * c12;
  const T x2 = one - det / (m * m);
  T f;  // atanh(x) / x = sum x^(2k) / (2k + 1)
  if (value_of(x2) < 1e-2) {
    f = lift<T>(1.0 / 17.0);
    for (int k = 7; k >= 0; --k) f = lift<T>(1.0 / (2.0 * k + 1.0)) + x2 * f;  // truncation < x^18 / 19 < 1e-19
  } else {
    const T x = sqrt(x2);
    f = half * log((one + x) / (one - x)) / x;
  }
  const T b = f / m;
  const T a = half * log(det) - b * m;
  Eigen::Matrix<T, 3, 1> eps;
  eps(0) = half * (a + b * c11);
  eps(1) = half * (a + b * c22);
  eps(2) = b * c12;
  return eps;
}

struct LogStrain {
  Eigen::Vector3d value;                // eps
  Eigen::Matrix3d first;                // d eps_i / d E_j
  std::array<Eigen::Matrix3d, 3> second{Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};  // second[i](j, k) = d2 eps_i / dE_j dE_k
};

// Value and first and second derivatives in closed form (second = false: `second` left zero, for
// a residual without tangent). Requires det C > 0 (checked by callers).
LogStrain log_strain_with_derivatives(const Eigen::Vector3d& green, bool second = true);
// The value alone, bit for bit that of log_strain_with_derivatives (the section's commit).
Eigen::Vector3d log_strain_value(const Eigen::Vector3d& green);

}  // namespace spifit::element
