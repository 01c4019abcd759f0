#pragma once
// Barlat et al. (2003) Yld2000-2d, the non-quadratic plane-stress yield function of aluminium
// sheets: two linear transformations of the stress, X' = L' sigma and X'' = L'' sigma (alpha1,
// alpha2, alpha7 and alpha3..alpha6, alpha8), and
//   2 sigma_eq^a = |X1' - X2'|^a + |2 X2'' + X1''|^a + |2 X1'' + X2''|^a
// with X1, X2 the principal values. All alphas = 1 is the isotropic Hershey-Hosford function,
// von Mises for a = 2 (and a = 4); a = 8 is usual for FCC metals (aluminium), 6 for BCC (steel).
//
// Written without principal values, so that it is smooth where they coincide: with D the
// quadratic form s(X) = ((Xxx - Xyy)/2)^2 + Xxy^2 (the squared half-difference of the principal
// values) and c = 3 (Xxx'' + Xyy'')/2,
//   phi' = (4 s(X'))^(a/2),  phi'' = g(c, s(X'')) = |c + sqrt(s)|^a + |c - sqrt(s)|^a,
// and g, even in sqrt(s), is differentiated in s (by its Taylor series in s where sqrt(s) is
// below 1e-3 |c|, where the closed-form derivatives lose digits). sigma_eq is homogeneous of
// degree one, so it is evaluated on xi / max|xi| (no overflow of |X|^8) and scaled back.
// docs/design/numerics-material.md, "A non-quadratic yield function: Yld2000-2d", gives the
// derivatives.
#include "forward/material/law_coefficient.hpp"
#include "forward/material/scalar.hpp"
#include "forward/material/yield/yield_function_coefficients.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace spifit::material {

struct Yld2000_2d {
  enum Coefficient { alpha1, alpha2, alpha3, alpha4, alpha5, alpha6, alpha7, alpha8, a, count };
  static constexpr const char* name = "yld2000";
  static constexpr const char* title = "Yld2000-2d (Barlat et al. 2003)";
  static constexpr const char* formula = "2 sigma_eq^a = |X1' - X2'|^a + |2 X2'' + X1''|^a + |2 X1'' + X2''|^a";
  // The smallest exponent served: a < 1 is not convex, and below 2 the Hessian the return
  // mapping needs is unbounded where the principal values of X' coincide.
  static constexpr double min_exponent = 2.0;

  static std::vector<LawCoefficient> coefficients() {
    using io::Range;
    return {{"alpha1", "", Range::any(), "Yld2000-2d alpha1 (L'xx)"},
            {"alpha2", "", Range::any(), "Yld2000-2d alpha2 (L'yy)"},
            {"alpha3", "", Range::any(), "Yld2000-2d alpha3 (L'')"},
            {"alpha4", "", Range::any(), "Yld2000-2d alpha4 (L'')"},
            {"alpha5", "", Range::any(), "Yld2000-2d alpha5 (L'')"},
            {"alpha6", "", Range::any(), "Yld2000-2d alpha6 (L'')"},
            {"alpha7", "", Range::any(), "Yld2000-2d alpha7 (L'xy, in-plane shear)"},
            {"alpha8", "", Range::any(), "Yld2000-2d alpha8 (L''xy, in-plane shear)"},
            {"a", "", Range::at_least(min_exponent), "Yld2000-2d exponent a (8 for aluminium, 6 for steel; 2 with all alphas 1 is von Mises)"}};
  }
  static std::vector<double> defaults() { return {1, 1, 1, 1, 1, 1, 1, 1, 8}; }

  template <typename T>
  using Vec = Eigen::Matrix<T, 3, 1>;
  template <typename T>
  using Mat = Eigen::Matrix<T, 3, 3>;

  // X' = L' sigma (Barlat et al. 2003, eq. 18): deviator-like, alpha1, alpha2, alpha7.
  template <typename T>
  static Mat<T> first_transform(const T* c) {
    Mat<T> L = Mat<T>::Zero();
    L(0, 0) = 2.0 * c[alpha1] / 3.0; L(0, 1) = -c[alpha1] / 3.0;
    L(1, 0) = -c[alpha2] / 3.0;      L(1, 1) = 2.0 * c[alpha2] / 3.0;
    L(2, 2) = c[alpha7];
    return L;
  }
  // X'' = L'' sigma (eq. 19): alpha3..alpha6, alpha8.
  template <typename T>
  static Mat<T> second_transform(const T* c) {
    Mat<T> L = Mat<T>::Zero();
    L(0, 0) = (-2.0 * c[alpha3] + 2.0 * c[alpha4] + 8.0 * c[alpha5] - 2.0 * c[alpha6]) / 9.0;
    L(0, 1) = (c[alpha3] - 4.0 * c[alpha4] - 4.0 * c[alpha5] + 4.0 * c[alpha6]) / 9.0;
    L(1, 0) = (4.0 * c[alpha3] - 4.0 * c[alpha4] - 4.0 * c[alpha5] + c[alpha6]) / 9.0;
    L(1, 1) = (-2.0 * c[alpha3] + 8.0 * c[alpha4] + 2.0 * c[alpha5] - 2.0 * c[alpha6]) / 9.0;
    L(2, 2) = c[alpha8];
    return L;
  }

  // sigma_eq(xi), its gradient and (if hessian) its Hessian.
  template <typename T>
  static void evaluate(const T* c, const Vec<T>& xi, YieldValue<T>& out, bool hessian) {
    using std::sqrt;
    out = YieldValue<T>();
    out.exponent = c[a];
    const double scale = std::max({std::abs(value_of(xi(0))), std::abs(value_of(xi(1))), std::abs(value_of(xi(2)))});
    if (!(scale > 0.0) || !std::isfinite(scale)) return;  // zero stress: no direction
    const Vec<T> x = xi / scale;
    const T& e = c[a];
    Mat<T> D = Mat<T>::Zero();  // s(X) = X^T D X / 2
    D(0, 0) = D(1, 1) = T(0.5); D(0, 1) = D(1, 0) = T(-0.5); D(2, 2) = T(2.0);

    // phi' = (4 s1)^(a/2)
    const Mat<T> L1 = first_transform(c);
    const Vec<T> X1 = L1 * x;
    const Vec<T> g1 = L1.transpose() * (D * X1);  // d s1 / d x
    const T s1 = 0.5 * X1.dot(D * X1);
    const bool s1_zero = !(value_of(s1) > 0.0);
    const T phi1 = s1_zero ? T(0.0) : power(T(4.0 * s1), T(0.5 * e));
    const T d1 = s1_zero ? (value_of(e) == 2.0 ? T(4.0) : T(0.0)) : 2.0 * e * power(T(4.0 * s1), T(0.5 * e - 1.0));
    const T dd1 = s1_zero || value_of(e) == 2.0 ? T(0.0) : 4.0 * e * (e - 2.0) * power(T(4.0 * s1), T(0.5 * e - 2.0));

    // phi'' = g(c2, s2)
    const Mat<T> L2 = second_transform(c);
    const Vec<T> X2 = L2 * x;
    const Vec<T> g2 = L2.transpose() * (D * X2);  // d s2 / d x
    const T s2 = 0.5 * X2.dot(D * X2);
    Vec<T> one_one(T(1.5), T(1.5), T(0.0));
    const Vec<T> gc = L2.transpose() * one_one;  // d c2 / d x
    const T c2 = gc.dot(x);
    const T delta = value_of(s2) > 0.0 ? sqrt(s2) : T(0.0);
    T g, g_c, g_s, g_cc, g_cs, g_ss;
    if (value_of(delta) <= 1e-3 * std::abs(value_of(c2))) {
      // Taylor series in s = delta^2 of h(c + delta) + h(c - delta), h(x) = |x|^a.
      const T h0 = h(e, 0, c2), h2 = h(e, 2, c2), h3 = h(e, 3, c2), h4 = h(e, 4, c2), h5 = h(e, 5, c2), h6 = h(e, 6, c2), h7 = h(e, 7, c2);
      const T h1 = h(e, 1, c2);
      g = 2.0 * h0 + h2 * s2 + h4 * s2 * s2 / 12.0 + h6 * s2 * s2 * s2 / 360.0;
      g_c = 2.0 * h1 + h3 * s2 + h5 * s2 * s2 / 12.0;
      g_s = h2 + h4 * s2 / 6.0 + h6 * s2 * s2 / 120.0;
      g_cc = 2.0 * h2 + h4 * s2 + h6 * s2 * s2 / 12.0;
      g_cs = h3 + h5 * s2 / 6.0 + h7 * s2 * s2 / 120.0;
      g_ss = h4 / 6.0 + h6 * s2 / 60.0;
    } else {
      const T u = c2 + delta, v = c2 - delta;
      const T hu1 = h(e, 1, u), hv1 = h(e, 1, v), hu2 = h(e, 2, u), hv2 = h(e, 2, v);
      g = h(e, 0, u) + h(e, 0, v);
      g_c = hu1 + hv1;
      g_s = (hu1 - hv1) / (2.0 * delta);
      g_cc = hu2 + hv2;
      g_cs = (hu2 - hv2) / (2.0 * delta);
      g_ss = ((hu2 + hv2) - (hu1 - hv1) / delta) / (4.0 * s2);
    }

    const T phi = phi1 + g;
    if (!(value_of(phi) > 0.0) || !is_finite(phi)) return;  // on a degenerate (open) surface
    const T sigma = power(T(0.5 * phi), T(1.0 / e));
    const Vec<T> dphi = d1 * g1 + g_c * gc + g_s * g2;
    const T k = sigma / (e * phi);
    out.value = scale * sigma;
    out.gradient = k * dphi;
    if (!hessian) return;
    const Mat<T> H1 = L1.transpose() * D * L1, H2 = L2.transpose() * D * L2;
    const Mat<T> ddphi = dd1 * (g1 * g1.transpose()) + d1 * H1 + g_cc * (gc * gc.transpose()) +
                         g_cs * (gc * g2.transpose() + g2 * gc.transpose()) + g_ss * (g2 * g2.transpose()) + g_s * H2;
    out.hessian = (k / scale) * (ddphi + ((1.0 / e - 1.0) / phi) * (dphi * dphi.transpose()));
  }

  // Empty when the coefficients give a closed convex yield surface; otherwise why not, with the
  // index of the coefficient to name.
  static std::string violation(const double* c, int& coefficient);

 private:
  // x^p for x >= 0 (0 for x = 0, p > 0).
  template <typename T>
  static T power(const T& x, const T& p) {
    if (!(value_of(x) > 0.0)) return value_of(p) == 0.0 ? T(1.0) : T(0.0);
    return real_power(x, p);
  }
  // The k-th derivative of |x|^e: e (e - 1) ... (e - k + 1) |x|^(e - k) sign(x)^k (0 where the
  // factor vanishes, and at x = 0 unless e = k).
  template <typename T>
  static T h(const T& e, int k, const T& x) {
    using std::abs;
    T f = T(1.0);
    for (int i = 0; i < k; ++i) f = f * (e - double(i));
    if (value_of(f) == 0.0) return T(0.0);
    const double xv = value_of(x);
    if (xv == 0.0) return value_of(e) == double(k) ? f : T(0.0);
    const T r = f * real_power(T(abs(x)), T(e - double(k)));
    return (k % 2 == 1 && xv < 0.0) ? T(-r) : r;
  }
};

inline std::string Yld2000_2d::violation(const double* c, int& coefficient) {
  static const char* keys[] = {"alpha1", "alpha2", "alpha3", "alpha4", "alpha5", "alpha6", "alpha7", "alpha8", "a"};
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(c[i])) return (coefficient = i), std::string(keys[i]) + " is not a finite number";
  coefficient = a;
  if (!(c[a] >= min_exponent))
    return "the exponent a must be >= 2 (a < 1 is not convex; below 2 the return mapping has no bounded Hessian)";
  // Convex for any alphas once a >= 1 (Barlat et al. 2003): what can fail is a closed surface.
  // sigma_eq vanishes only where X'' = 0 and X' is isotropic: a nonzero stress in the kernel of
  // L'' (3 x 3, block diagonal) that L' maps onto an isotropic X'.
  const Mat<double> L1 = first_transform(c), L2 = second_transform(c);
  const Eigen::Matrix<double, 2, 2> B = L2.topLeftCorner<2, 2>();
  const double norm = std::max(B.cwiseAbs().maxCoeff(), 1e-300);
  coefficient = alpha8;
  if (std::abs(c[alpha7]) <= 1e-12 && std::abs(c[alpha8]) <= 1e-12)
    return "alpha7 and alpha8 are both zero: the yield surface is open along pure shear (no shear yield stress)";
  if (std::abs(B.determinant()) <= 1e-12 * norm * norm) {
    // The kernel of the normal block, n: X' isotropic needs X'xx = X'yy, i.e. (L1 row 0 - row 1) n = 0.
    Eigen::Vector2d n(-B(0, 1), B(0, 0));
    if (n.norm() == 0.0) n = Eigen::Vector2d(-B(1, 1), B(1, 0));
    if (n.norm() == 0.0) n = Eigen::Vector2d(1.0, 0.0);
    n.normalize();
    const double diff = (L1(0, 0) - L1(1, 0)) * n(0) + (L1(0, 1) - L1(1, 1)) * n(1);
    const double ref = std::max(L1.cwiseAbs().maxCoeff(), 1e-300);
    if (std::abs(diff) <= 1e-12 * ref) {
      coefficient = alpha3;
      char buf[200];
      std::snprintf(buf, sizeof buf, "sigma_eq vanishes for the stress (sxx, syy) = (%.4g, %.4g): the yield surface is open", n(0), n(1));
      return buf;
    }
  }
  return {};
}

}  // namespace spifit::material
