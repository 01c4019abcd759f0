#pragma once
// Combined Swift-Voce hardening, a weighted sum of the two:
//   sigma_F(p) = alpha K (eps0 + p)^n + (1 - alpha) [sigma0 + Q (1 - exp(-b p))].
// Swift's growth and Voce's saturation in one curve: alpha = 1 is Swift, alpha = 0 is Voce. The
// coefficients keep the two laws' keys.
#include "forward/material/hardening/hardening_coefficients.hpp"

#include <cmath>
#include <vector>

namespace spifit::material {

struct SwiftVoceHardening {
  enum Coefficient { K, eps0, n, sigma0, Q, b, alpha, count };
  static constexpr const char* name = "swift_voce";
  static constexpr const char* title = "Swift-Voce";
  static constexpr const char* formula = "sigma_F = alpha K (eps0 + p)^n + (1 - alpha) (sigma0 + Q (1 - exp(-b p)))";
  static constexpr const char* initial_formula = "alpha K eps0^n + (1 - alpha) sigma0";

  static std::vector<HardeningCoefficient> coefficients() {
    return {{"K", "MPa", io::Range::positive(), "Swift-Voce: Swift strength coefficient K"},
            {"eps0", "", io::Range::positive(), "Swift-Voce: Swift prestrain eps0"},
            {"n", "", io::Range{0.0, 1.0, false, true}, "Swift-Voce: Swift hardening exponent n"},
            {"sigma0", "MPa", io::Range::positive(), "Swift-Voce: Voce initial yield stress sigma0"},
            {"Q", "MPa", io::Range::non_negative(), "Swift-Voce: Voce saturation increase Q"},
            {"b", "", io::Range::non_negative(), "Swift-Voce: Voce saturation rate b"},
            {"alpha", "", io::Range::closed(0.0, 1.0), "Swift-Voce weight of the Swift part (1: Swift, 0: Voce)"}};
  }

  template <typename T>
  static T stress(const T* c, const T& p) {
    using std::expm1;
    using std::pow;
    return c[alpha] * c[K] * pow(c[eps0] + p, c[n]) + (1.0 - c[alpha]) * (c[sigma0] - c[Q] * expm1(-c[b] * p));
  }
  template <typename T>
  static T slope(const T* c, const T& p0, const T& dl, const T& /*s*/) {
    using std::exp;
    using std::pow;
    const T p = p0 + dl;
    return c[alpha] * c[n] * c[K] * pow(c[eps0] + p, c[n] - 1.0) + (1.0 - c[alpha]) * c[Q] * c[b] * exp(-c[b] * p);
  }
  static void scale_strain(double* c, double h) {
    c[K] = c[K] * std::pow(h, -(1.0 + c[n]));
    c[eps0] = h * c[eps0];
    c[sigma0] /= h;
    c[Q] /= h;
    c[b] /= h;
  }
  static double resolution_strain(const double* c) { return c[eps0]; }
};

}  // namespace spifit::material
