#pragma once
// Voce isotropic hardening, saturating: sigma_F(p) = sigma0 + Q (1 - exp(-b p)). Aluminium
// alloys saturate at large strain where Swift grows without bound; Q = 0 or b = 0 is perfect
// plasticity at sigma0.
#include "forward/material/hardening/hardening_coefficients.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace spifit::material {

struct VoceHardening {
  enum Coefficient { sigma0, Q, b, count };
  static constexpr const char* name = "voce";
  static constexpr const char* title = "Voce";
  static constexpr const char* formula = "sigma_F = sigma0 + Q (1 - exp(-b p))";
  static constexpr const char* initial_formula = "sigma0";

  static std::vector<HardeningCoefficient> coefficients() {
    return {{"sigma0", "MPa", io::Range::positive(), "Voce sigma_F = sigma0 + Q (1 - exp(-b p)): initial yield stress"},
            {"Q", "MPa", io::Range::non_negative(), "Voce saturation increase Q (sigma_F -> sigma0 + Q)"},
            {"b", "", io::Range::non_negative(), "Voce saturation rate b"}};
  }

  template <typename T>
  static T stress(const T* c, const T& p) {
    using std::expm1;
    return c[sigma0] - c[Q] * expm1(-c[b] * p);
  }
  template <typename T>
  static T slope(const T* c, const T& p0, const T& dl, const T& /*s*/) {
    using std::exp;
    return c[Q] * c[b] * exp(-c[b] * (p0 + dl));
  }
  static void scale_strain(double* c, double h) {
    c[sigma0] /= h;
    c[Q] /= h;
    c[b] /= h;
  }
  static double resolution_strain(const double* /*c*/) { return std::numeric_limits<double>::infinity(); }
};

}  // namespace spifit::material
