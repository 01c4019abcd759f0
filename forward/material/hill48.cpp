#include "forward/material/hill48.hpp"

#include <cmath>
#include <sstream>

namespace spifit::material {

bool Hill48::is_von_mises(double tol) const {
  return std::abs(F - 1) < tol && std::abs(G - 1) < tol && std::abs(H - 1) < tol &&
         std::abs(L - 3) < tol && std::abs(M - 3) < tol && std::abs(N - 3) < tol;
}

Hill48 hill_from_lankford(const Lankford& r) {
  Hill48 h;
  h.G = 2.0 / (1.0 + r.r0);
  h.H = 2.0 - h.G;
  h.F = h.H / r.r90;
  h.N = (h.F + h.G) * (r.r45 + 0.5);
  h.L = h.N;
  h.M = h.N;
  return h;
}

Lankford lankford_from_hill(const Hill48& h) {
  return {h.H / h.G, (2.0 * h.N - h.F - h.G) / (2.0 * (h.F + h.G)), h.H / h.F};
}

double r_value_at_angle(const Hill48& h, double alpha) {
  const double s = std::sin(alpha), c = std::cos(alpha);
  const double s2c2 = s * s * c * c;
  return (h.H + (2.0 * h.N - h.F - h.G - 4.0 * h.H) * s2c2) / (h.F * s * s + h.G * c * c);
}

double uniaxial_stress_factor(const Hill48& h, double alpha) {
  const double s = std::sin(alpha), c = std::cos(alpha);
  const double sxx = c * c, syy = s * s, sxy = s * c;
  const double q = h.H * (sxx - syy) * (sxx - syy) + h.G * sxx * sxx + h.F * syy * syy +
                   2.0 * h.N * sxy * sxy;
  return std::sqrt(0.5 * q);
}

double shear_stress_factor(const Hill48& h) { return std::sqrt(h.N); }

AbaqusPotential abaqus_potential_from_hill(const Hill48& h) {
  return {std::sqrt(2.0 / (h.G + h.H)), std::sqrt(2.0 / (h.F + h.H)), std::sqrt(2.0 / (h.F + h.G)),
          std::sqrt(3.0 / h.N),         std::sqrt(3.0 / h.L),         std::sqrt(3.0 / h.M)};
}

Hill48 hill_from_abaqus_potential(const AbaqusPotential& r) {
  const double a = 1.0 / (r.R11 * r.R11), b = 1.0 / (r.R22 * r.R22), c = 1.0 / (r.R33 * r.R33);
  Hill48 h;
  // G + H = 2a, F + H = 2b, F + G = 2c.
  h.F = b + c - a;
  h.G = a + c - b;
  h.H = a + b - c;
  h.N = 3.0 / (r.R12 * r.R12);
  h.L = 3.0 / (r.R13 * r.R13);
  h.M = 3.0 / (r.R23 * r.R23);
  return h;
}

std::string hill_convexity_violation(const Hill48& h) {
  std::ostringstream os;
  const double det = h.F * h.G + h.G * h.H + h.H * h.F;
  if (!(det > 0)) os << "FG + GH + HF = " << det << " must be > 0";
  else if (!(h.F + h.G > 0)) os << "F + G = " << h.F + h.G << " must be > 0";
  else if (!(h.G + h.H > 0)) os << "G + H = " << h.G + h.H << " must be > 0";
  else if (!(h.H + h.F > 0)) os << "H + F = " << h.H + h.F << " must be > 0";
  else if (!(h.L > 0)) os << "L = " << h.L << " must be > 0";
  else if (!(h.M > 0)) os << "M = " << h.M << " must be > 0";
  else if (!(h.N > 0)) os << "N = " << h.N << " must be > 0";
  return os.str();
}

}  // namespace spifit::material
