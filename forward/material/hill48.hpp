#pragma once
// Hill 1948 anisotropic yield criterion in the thesis's notation (eq. 3.5/3.6):
//   sigma_eq^2 = 1/2 [H(sxx-syy)^2 + G(sxx-szz)^2 + F(syy-szz)^2 + 2N sxy^2 + 2L sxz^2 + 2M syz^2]
// Von Mises is F = G = H = 1, N = L = M = 3. Note the factor 1/2: Abaqus, LS-DYNA and MFront
// write Hill without it, so these coefficients are twice theirs, and the thesis attaches L to
// xz and M to yz (Hill and Abaqus use L for yz and M for zx).
#include <string>

namespace spifit::material {

struct Hill48 {
  double F = 1.0, G = 1.0, H = 1.0;
  double L = 3.0, M = 3.0, N = 3.0;

  static Hill48 von_mises() { return {}; }
  bool is_von_mises(double tol = 1e-12) const;
};

// Lankford coefficients r = plastic width / thickness strain rate (thesis eq. C.1).
struct Lankford {
  double r0 = 1.0, r45 = 1.0, r90 = 1.0;
};

// eq. C.3 with the usual normalisation G + H = 2 and N = L = M.
Hill48 hill_from_lankford(const Lankford& r);
// eq. C.2.
Lankford lankford_from_hill(const Hill48& h);

// Closed-form r-value of a uniaxial tension at angle alpha (radians) from RD:
//   r(a) = [H + (2N - F - G - 4H) s^2 c^2] / (F s^2 + G c^2).
double r_value_at_angle(const Hill48& h, double alpha);
// Equivalent stress of a unit uniaxial stress at angle alpha: sigma_eq = factor * sigma.
double uniaxial_stress_factor(const Hill48& h, double alpha);
// Equivalent stress of a unit in-plane pure shear (tau_xy = 1): sqrt(N).
double shear_stress_factor(const Hill48& h);

// Abaqus *POTENTIAL stress ratios (reference stress = the yield stress along RD for G + H = 2).
// R11 = sqrt(2/(G+H)), R22 = sqrt(2/(F+H)), R33 = sqrt(2/(F+G)), R12 = sqrt(3/N),
// R13 = sqrt(3/L_thesis) (xz), R23 = sqrt(3/M_thesis) (yz).
struct AbaqusPotential {
  double R11 = 1.0, R22 = 1.0, R33 = 1.0, R12 = 1.0, R13 = 1.0, R23 = 1.0;
};
AbaqusPotential abaqus_potential_from_hill(const Hill48& h);
Hill48 hill_from_abaqus_potential(const AbaqusPotential& r);

// Empty when the coefficients give a convex, bounded-in-deviatoric-space yield surface
// (FG + GH + HF > 0, F+G, G+H, H+F > 0, L, M, N > 0); otherwise the first violated condition.
std::string hill_convexity_violation(const Hill48& h);

}  // namespace spifit::material
