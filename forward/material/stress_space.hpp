#pragma once
// The two stress spaces served by one return-mapping core (docs/design/numerics-material.md,
// "Conventions" and "Plane stress: exact reduction"):
//  * Dim = 6, full 3D, Voigt order xx, yy, zz, xy, xz, yz;
//  * Dim = 3, plane stress (szz = sxz = syz = 0), order xx, yy, xy.
// Stress vectors hold tensor components; strain vectors hold ENGINEERING shear strains
// (gamma = 2 eps), so that stress . strain is the work density.
//
// Plane stress is reduced exactly to the in-plane components: because Hill's matrix
// annihilates hydrostatic stress, sigma_eq(sigma - X) with szz = 0 equals the in-plane
// criterion applied to sigma_p - X~, where X~ = (Xxx - Xzz, Xyy - Xzz, Xxy). X~ evolves like X
// with the plastic-strain map A below (using eps_p_zz = -(eps_p_xx + eps_p_yy)).
#include "forward/material/material_params.hpp"

#include <Eigen/Core>

namespace spifit::material {

template <typename T, int Dim>
struct StressSpace;

template <typename T>
struct StressSpace<T, 6> {
  using Vec = Eigen::Matrix<T, 6, 1>;
  using Mat = Eigen::Matrix<T, 6, 6>;
  static constexpr bool plane_stress = false;

  static Mat elastic(const MaterialParams<T>& m) {
    const T lambda = m.E * m.nu / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu));
    const T mu = m.E / (2.0 * (1.0 + m.nu));
    Mat C = Mat::Zero();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) C(i, j) = lambda;
      C(i, i) = lambda + 2.0 * mu;
      C(i + 3, i + 3) = mu;
    }
    return C;
  }
  // sigma_eq^2 = 1/2 s^T P s (thesis eq. 3.6).
  static Mat hill(const MaterialParams<T>& m) {
    Mat P = Mat::Zero();
    P(0, 0) = m.G + m.H; P(0, 1) = -m.H;        P(0, 2) = -m.G;
    P(1, 0) = -m.H;      P(1, 1) = m.H + m.F;   P(1, 2) = -m.F;
    P(2, 0) = -m.G;      P(2, 1) = -m.F;        P(2, 2) = m.F + m.G;
    P(3, 3) = 2.0 * m.N; P(4, 4) = 2.0 * m.L;   P(5, 5) = 2.0 * m.M;
    return P;
  }
  // Maps an engineering plastic strain increment onto tensor components (Armstrong-Frederick).
  static Mat kinematic_map() {
    Mat A = Mat::Identity();
    A(3, 3) = A(4, 4) = A(5, 5) = T(0.5);
    return A;
  }
};

template <typename T>
struct StressSpace<T, 3> {
  using Vec = Eigen::Matrix<T, 3, 1>;
  using Mat = Eigen::Matrix<T, 3, 3>;
  static constexpr bool plane_stress = true;

  static Mat elastic(const MaterialParams<T>& m) {
    const T f = m.E / (1.0 - m.nu * m.nu);
    Mat C = Mat::Zero();
    C(0, 0) = f; C(0, 1) = f * m.nu;
    C(1, 0) = f * m.nu; C(1, 1) = f;
    C(2, 2) = m.E / (2.0 * (1.0 + m.nu));
    return C;
  }
  static Mat hill(const MaterialParams<T>& m) {
    Mat P = Mat::Zero();
    P(0, 0) = m.G + m.H; P(0, 1) = -m.H;
    P(1, 0) = -m.H;      P(1, 1) = m.H + m.F;
    P(2, 2) = 2.0 * m.N;
    return P;
  }
  // (d eps_p_xx - d eps_p_zz, d eps_p_yy - d eps_p_zz, d gamma_p_xy / 2) with
  // d eps_p_zz = -(d eps_p_xx + d eps_p_yy).
  static Mat kinematic_map() {
    Mat A = Mat::Zero();
    A(0, 0) = T(2.0); A(0, 1) = T(1.0);
    A(1, 0) = T(1.0); A(1, 1) = T(2.0);
    A(2, 2) = T(0.5);
    return A;
  }
};

}  // namespace spifit::material
