#pragma once
// Armstrong-Frederick kinematic hardening (thesis eq. 3.8, the last term read as a rate):
//   dX = C_X (X_sat A d eps_p - X dp),
// integrated exponentially over a step with the end-of-step flow direction:
//   X1 = m X0 + k psi(C_X dl) A d eps_p,   m = exp(-C_X dl),  k = C_X X_sat,  psi(x) = (1 - e^-x)/x.
#include "forward/io/input_error.hpp"
#include "forward/material/kinematic/kinematic_coefficients.hpp"
#include "forward/material/scalar.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace spifit::material {

struct ArmstrongFrederick {
  enum Coefficient { CX, Xsat, count };
  static constexpr const char* name = "armstrong_frederick";  // card table
  static constexpr const char* input_prefix = "af";           // fit names af.CX, af.Xsat
  static constexpr const char* title = "Armstrong-Frederick";

  static std::vector<LawCoefficient> coefficients() {
    return {{"CX", "", io::Range::non_negative(), "Armstrong-Frederick rate C_X (eq. 3.8)"},
            {"Xsat", "MPa", io::Range::non_negative(), "Armstrong-Frederick saturation X_sat"}};
  }

  // e = k psi(C_X dl) (the back-stress follows the plastic strain), m = exp(-C_X dl).
  template <typename T>
  static void step(const T* c, const T& dl, const T& /*s*/, const T& /*ds*/, KinematicStep<T>& k) {
    using std::exp;
    const T x = c[CX] * dl;
    const T kk = c[CX] * c[Xsat];
    k.e = kk * psi_exp(x);
    k.de = kk * c[CX] * psi_exp_derivative(x);
    k.m = exp(-x);
    k.dm = -c[CX] * k.m;
  }
  // Plane stress: the back-stress's zz component, X_zz1 = m X_zz0 + e d eps_p_zz.
  template <typename T>
  static T back_stress_zz(const T* /*c*/, const KinematicStep<T>& k, const T& x0_zz, const T& d_eps_p_zz) {
    return k.m * x0_zz + k.e * d_eps_p_zz;
  }
  // What `spifit material show` adds after the constants.
  static std::string saturation(const double* c) {
    return " (uniaxial von Mises offset saturates at 1.5 Xsat = " + io::format_number(1.5 * c[Xsat]) + " MPa)";
  }
  // Decay rate of the back-stress per unit plastic strain (the scenes bound rate * dl per step).
  template <typename T>
  static double rate(const T* c, const T& /*flow_stress*/) {
    return value_of(c[CX]);
  }
};

}  // namespace spifit::material
