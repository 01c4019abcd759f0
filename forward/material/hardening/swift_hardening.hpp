#pragma once
// Swift isotropic hardening (thesis eq. 3.7): sigma_F(p) = K (eps0 + p)^n. n = 0 gives perfect
// plasticity at sigma_F = K. The law every card of the thesis uses (Tables C.1-C.8).
#include "forward/material/hardening/hardening_coefficients.hpp"

#include <cmath>
#include <vector>

namespace spifit::material {

struct SwiftHardening {
  enum Coefficient { K, eps0, n, count };
  static constexpr const char* name = "swift";  // card table [swift], fit names "swift.K"
  static constexpr const char* title = "Swift";
  static constexpr const char* formula = "sigma_F = K (eps0 + p)^n";
  static constexpr const char* initial_formula = "K eps0^n";

  static std::vector<HardeningCoefficient> coefficients() {
    return {{"K", "MPa", io::Range::positive(), "Swift sigma_F = K (eps0 + p)^n: strength coefficient (eq. 3.7)"},
            {"eps0", "", io::Range::positive(), "Swift prestrain eps0"},
            {"n", "", io::Range{0.0, 1.0, false, true}, "Swift hardening exponent (0: perfectly plastic)"}};
  }

  template <typename T>
  static T stress(const T* c, const T& p) {
    using std::pow;
    return c[K] * pow(c[eps0] + p, c[n]);
  }
  // d sigma_F / dp at p = p0 + dl, given s = stress(p): n s / (eps0 + p), no second pow.
  template <typename T>
  static T slope(const T* c, const T& p0, const T& dl, const T& s) {
    return c[n] * s / (c[eps0] + p0 + dl);
  }
  // The coefficients of sigma_F(p / h) / h (the RD-normalised law of the FE decks).
  static void scale_strain(double* c, double h) {
    c[K] = c[K] * std::pow(h, -(1.0 + c[n]));
    c[eps0] = h * c[eps0];
  }
  // The smallest plastic strain the law's shape depends on: hardening tables start below it.
  static double resolution_strain(const double* c) { return c[eps0]; }
};

}  // namespace spifit::material
