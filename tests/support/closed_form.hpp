#pragma once
// Closed-form material-point responses used as references (derivations in
// docs/design/numerics-material.md). All in Kirchhoff stress vs the law's strain measure.
#include "forward/material/hill48.hpp"
#include "forward/material/material_params.hpp"
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"

#include <cmath>
#include <functional>

namespace spifit::test {


// Equivalent plastic strain p at which a closed form's total strain reaches `strain`
// (strain_at_p is monotonic in p): bisection to round-off.
template <typename ClosedForm>
double plastic_strain_at(const ClosedForm& cf, double strain, double p_max) {
  double lo = 0.0, hi = p_max;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (cf.strain_at_p(mid) < strain ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
using material::MaterialParams;

// Uniaxial stress along alpha (Hill + Swift + isotropic, or von Mises + AF / Ziegler):
//   tau = sigma_F(p)/h + offset(p), eps = tau/E + h p   (h = Hill uniaxial factor).
struct UniaxialClosedForm {
  MaterialParams<double> m;
  double h = 1.0;  // sigma_eq of a unit uniaxial stress
  double offset(double p) const {
    using AF = material::ArmstrongFrederick;
    using Z = material::Ziegler;
    const auto& k = m.kinematic;
    if (material::is_kinematic<AF>(k)) return 1.5 * k[AF::Xsat] * (1.0 - std::exp(-k[AF::CX] * p));
    if (material::is_kinematic<Z>(k)) return k[Z::CA] / k[Z::GA] * (1.0 - std::exp(-k[Z::GA] * p));
    return 0.0;
  }
  double stress_at_p(double p) const { return material::hardening_stress(m, p) / h + offset(p); }
  double strain_at_p(double p) const { return stress_at_p(p) / m.E + h * p; }
  // Stress for a total (monotonic, tensile) strain.
  double stress(double eps) const {
    if (eps * m.E <= stress_at_p(0.0)) return eps * m.E;
    return stress_at_p(plastic_strain_at(*this, eps, eps / h));
  }
};

// Simple shear at alpha = 0 (pure shear stress tau_xy), any card:
//   tau = sigma_F(p)/sqrt(N) + Xxy(p), gamma = tau/mu + sqrt(N) p,
//   AF: Xxy = sqrt(N) Xsat/2 (1 - e^{-CX p}); Ziegler: Xxy = CA/(sqrt(N) GA)(1 - e^{-GA p}).
struct ShearClosedForm {
  MaterialParams<double> m;
  double back_stress(double p) const {
    const double r = std::sqrt(m.N);
    using AF = material::ArmstrongFrederick;
    using Z = material::Ziegler;
    const auto& k = m.kinematic;
    if (material::is_kinematic<AF>(k)) return r * k[AF::Xsat] / 2.0 * (1.0 - std::exp(-k[AF::CX] * p));
    if (material::is_kinematic<Z>(k)) return k[Z::CA] / (r * k[Z::GA]) * (1.0 - std::exp(-k[Z::GA] * p));
    return 0.0;
  }
  double mu() const { return m.E / (2.0 * (1.0 + m.nu)); }
  double stress_at_p(double p) const { return material::hardening_stress(m, p) / std::sqrt(m.N) + back_stress(p); }
  double strain_at_p(double p) const { return stress_at_p(p) / mu() + std::sqrt(m.N) * p; }
  double stress(double gamma) const {
    if (!m.plastic || gamma * mu() <= stress_at_p(0.0)) return gamma * mu();
    return stress_at_p(plastic_strain_at(*this, gamma, gamma));
  }
};

}  // namespace spifit::test
