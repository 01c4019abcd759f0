#pragma once
// Constitutive parameters of the Hill48 (or a registered yield function) + isotropic hardening (a law of the registry,
// hardening/hardening_laws.hpp: Swift, Voce, Swift-Voce) + kinematic hardening (none or a law of
// kinematic/kinematic_laws.hpp: Armstrong-Frederick, Ziegler) law,
// templated on the scalar type so that ceres::Jet gives exact parameter derivatives of a
// material-point curve (docs/design/numerics-material.md, "Jets (exact parameter derivatives)").
#include "forward/material/hardening/hardening_coefficients.hpp"
#include "forward/material/kinematic/kinematic_coefficients.hpp"
#include "forward/material/scalar.hpp"
#include "forward/material/yield/yield_function_coefficients.hpp"

#include <string>

namespace spifit::material {

template <typename T>
struct MaterialParams {
  // Isotropic elasticity [MPa, -].
  T E = T(72600.0), nu = T(0.36);
  // The yield function: Hill 1948 (yield.law = -1, the default), thesis notation (factor 1/2, L on
  // xz, M on yz), or a function of the registry (yield/yield_functions.hpp: Yld2000-2d), whose
  // coefficients `yield` holds; F..N are then unused.
  YieldFunction<T> yield;
  T F = T(1.0), G = T(1.0), H = T(1.0), L = T(3.0), M = T(3.0), N = T(3.0);
  // Isotropic hardening sigma_F(p): the law's index and coefficients (hardening_laws.hpp); the
  // default is Swift K = 180 MPa, eps0 = 0.00109, n = 0.21. plastic = false: an elastic card.
  bool plastic = true;
  Hardening<T> hardening{0, {T(180.0), T(0.00109), T(0.21)}};
  // Kinematic hardening: none (law -1) or the law's index and coefficients (kinematic_laws.hpp),
  // e.g. Armstrong-Frederick (eq. 3.8) dX = CX (Xsat deps_p - X dp), Ziegler (eq. 3.9)
  // dX = CA (sigma - X) dp / sigma_F - GA X dp.
  Kinematic<T> kinematic;

  // Every parameter through f (the laws and flags kept), e.g. to fewer derivative slots.
  template <typename U, typename Fn>
  MaterialParams<U> map(Fn f) const {
    MaterialParams<U> o;
    o.E = f(E); o.nu = f(nu);
    o.F = f(F); o.G = f(G); o.H = f(H); o.L = f(L); o.M = f(M); o.N = f(N);
    o.yield.law = yield.law;
    for (int i = 0; i < kMaxYieldCoefficients; ++i) o.yield[i] = f(yield[i]);
    o.plastic = plastic; o.hardening.law = hardening.law;
    for (int i = 0; i < kMaxHardeningCoefficients; ++i) o.hardening[i] = f(hardening[i]);
    o.kinematic.law = kinematic.law;
    for (int i = 0; i < kMaxKinematicCoefficients; ++i) o.kinematic[i] = f(kinematic[i]);
    return o;
  }

  template <typename U>
  MaterialParams<U> cast() const {
    return map<U>([](const T& x) { return U(x); });
  }
};

// Values of a (possibly Jet) parameter set.
template <typename T>
MaterialParams<double> values_of(const MaterialParams<T>& p) {
  return p.template map<double>([](const T& x) { return value_of(x); });
}

}  // namespace spifit::material
