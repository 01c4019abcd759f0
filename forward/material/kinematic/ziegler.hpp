#pragma once
// Ziegler kinematic hardening (thesis eq. 3.9): dX = C_A (sigma - X) dp / sigma_F - G_A X dp,
// integrated exponentially over a step with the end-of-step shifted stress xi = sigma - X:
//   X1 = m X0 + psi(G_A dl) dl C_A xi / sigma_F,   m = exp(-G_A dl).
#include "forward/io/input_error.hpp"
#include "forward/material/kinematic/kinematic_coefficients.hpp"
#include "forward/material/scalar.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace spifit::material {

struct Ziegler {
  enum Coefficient { CA, GA, count };
  static constexpr const char* name = "ziegler";
  static constexpr const char* input_prefix = "ziegler";
  static constexpr const char* title = "Ziegler";

  static std::vector<LawCoefficient> coefficients() {
    return {{"CA", "MPa", io::Range::non_negative(), "Ziegler C_A (eq. 3.9)"}, {"GA", "", io::Range::non_negative(), "Ziegler G_A"}};
  }

  // a = 1 + C_A psi dl / sigma_F (xi appears on both sides), m = exp(-G_A dl); s = sigma_F(p0 + dl), ds its slope.
  template <typename T>
  static void step(const T* c, const T& dl, const T& s, const T& ds, KinematicStep<T>& k) {
    using std::exp;
    const T x = c[GA] * dl;
    const T psi = psi_exp(x);
    k.a = 1.0 + c[CA] * psi * dl / s;
    k.da = c[CA] * (c[GA] * psi_exp_derivative(x) * dl / s + psi / s - psi * dl * ds / (s * s));
    k.m = exp(-x);
    k.dm = -c[GA] * k.m;
  }
  // Plane stress: X_zz1 = m X_zz0 / a (0 from a virgin state).
  template <typename T>
  static T back_stress_zz(const T* /*c*/, const KinematicStep<T>& k, const T& x0_zz, const T& /*d_eps_p_zz*/) {
    return k.m * x0_zz / k.a;
  }
  static std::string saturation(const double* c) {
    return c[GA] > 0 ? " (uniaxial offset saturates at CA/GA = " + io::format_number(c[CA] / c[GA]) + " MPa)" : std::string();
  }
  template <typename T>
  static double rate(const T* c, const T& flow_stress) {
    return value_of(c[GA] + c[CA] / flow_stress);
  }
};

}  // namespace spifit::material
