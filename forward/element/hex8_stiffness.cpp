#include "forward/element/hex8_stiffness.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace spifit::element {

namespace {

constexpr double kCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};

// The eight 2 x 2 x 2 Gauss points (weights 1).
Eigen::Vector3d gauss_point(int p) {
  const double g = 1.0 / std::sqrt(3.0);
  return g * Eigen::Vector3d(kCorner[p][0], kCorner[p][1], kCorner[p][2]);
}

double checked_determinant(const Eigen::Matrix3d& J, int p) {
  const double det = J.determinant();
  if (!(det > 0.0))
    throw std::invalid_argument("hexahedron: Jacobian " + std::to_string(det) + " <= 0 at Gauss point " + std::to_string(p) +
                                " (inverted or badly ordered corners)");
  return det;
}

// Voigt strain rows of n displacement functions with gradients grad (3 x n), 3 DOFs each.
template <int N>
Eigen::Matrix<double, 6, 3 * N> strain_rows(const Eigen::Matrix<double, 3, N>& grad) {
  Eigen::Matrix<double, 6, 3 * N> B = Eigen::Matrix<double, 6, 3 * N>::Zero();
  for (int I = 0; I < N; ++I) {
    const int c = 3 * I;
    B(0, c) = grad(0, I);
    B(1, c + 1) = grad(1, I);
    B(2, c + 2) = grad(2, I);
    B(3, c) = grad(1, I);
    B(3, c + 1) = grad(0, I);
    B(4, c) = grad(2, I);
    B(4, c + 2) = grad(0, I);
    B(5, c + 1) = grad(2, I);
    B(5, c + 2) = grad(1, I);
  }
  return B;
}

// Nodal values of hourglass function a (eta zeta, zeta xi, xi eta, xi eta zeta).
double hourglass_value(int a, int I) {
  const double xi = kCorner[I][0], eta = kCorner[I][1], zeta = kCorner[I][2];
  switch (a) {
    case 0: return eta * zeta;
    case 1: return zeta * xi;
    case 2: return xi * eta;
    default: return xi * eta * zeta;
  }
}

}  // namespace

Eigen::Matrix<double, 3, 8> hex_parent_derivatives(const Eigen::Vector3d& s) {
  Eigen::Matrix<double, 3, 8> dN;
  for (int I = 0; I < 8; ++I) {
    const double a = 1 + kCorner[I][0] * s(0), b = 1 + kCorner[I][1] * s(1), c = 1 + kCorner[I][2] * s(2);
    dN.col(I) << kCorner[I][0] * b * c / 8, kCorner[I][1] * a * c / 8, kCorner[I][2] * a * b / 8;
  }
  return dN;
}

Eigen::Matrix3d hex_jacobian(const HexCorners& X, const Eigen::Matrix<double, 3, 8>& dN) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (int I = 0; I < 8; ++I) J += dN.col(I) * X[static_cast<std::size_t>(I)].transpose();
  return J;
}

Voigt6Matrix isotropic_elasticity(double E, double nu) {
  Voigt6Matrix D = Voigt6Matrix::Zero();
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  D.topLeftCorner<3, 3>().setConstant(lambda);
  D.topLeftCorner<3, 3>().diagonal().array() += 2 * mu;
  D.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
  return D;
}

HexUniformGradient hex_uniform_gradient(const HexCorners& X) {
  // The integrand (cofactors of J times dN/ds) is at most cubic in each parent coordinate:
  // two Gauss points per direction integrate it exactly.
  HexUniformGradient g;
  g.b.setZero();
  for (int p = 0; p < 8; ++p) {
    const Eigen::Matrix<double, 3, 8> dN = hex_parent_derivatives(gauss_point(p));
    const Eigen::Matrix3d J = hex_jacobian(X, dN);
    const double det = checked_determinant(J, p);
    g.b += J.inverse() * dN * det;
    g.volume += det;
  }
  g.b /= g.volume;
  return g;
}

Eigen::Matrix<double, 6, 24> hex_strain_matrix(const Eigen::Matrix<double, 3, 8>& b) { return strain_rows<8>(b); }

Eigen::Matrix<double, 12, 24> hex_hourglass_operator(const HexCorners& X, const HexUniformGradient& g) {
  Eigen::Matrix<double, 12, 24> G = Eigen::Matrix<double, 12, 24>::Zero();
  for (int a = 0; a < 4; ++a) {
    Eigen::Matrix<double, 8, 1> h, gamma;
    for (int I = 0; I < 8; ++I) h(I) = hourglass_value(a, I);
    gamma = h;
    for (int k = 0; k < 3; ++k) {
      double hx = 0.0;  // h . x_k
      for (int I = 0; I < 8; ++I) hx += h(I) * X[static_cast<std::size_t>(I)](k);
      gamma -= hx * g.b.row(k).transpose();
    }
    gamma /= 8.0;
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) G(3 * a + i, 3 * I + i) = gamma(I);
  }
  return G;
}

Eigen::Matrix<double, 24, 12> hex_hourglass_shapes() {
  Eigen::Matrix<double, 24, 12> H = Eigen::Matrix<double, 24, 12>::Zero();
  for (int a = 0; a < 4; ++a)
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) H(3 * I + i, 3 * a + i) = hourglass_value(a, I);
  return H;
}

HexMatrix hex_one_point_stiffness(const HexCorners& X, const Voigt6Matrix& D) {
  const HexUniformGradient g = hex_uniform_gradient(X);
  const Eigen::Matrix<double, 6, 24> B = hex_strain_matrix(g.b);
  return g.volume * B.transpose() * D * B;
}

HexMatrix hex_full_stiffness(const HexCorners& X, const Voigt6Matrix& D) {
  HexMatrix K = HexMatrix::Zero();
  for (int p = 0; p < 8; ++p) {
    const Eigen::Matrix<double, 3, 8> dN = hex_parent_derivatives(gauss_point(p));
    const Eigen::Matrix3d J = hex_jacobian(X, dN);
    const double det = checked_determinant(J, p);
    const Eigen::Matrix<double, 6, 24> B = strain_rows<8>(Eigen::Matrix<double, 3, 8>(J.inverse() * dN));
    K += B.transpose() * D * B * det;
  }
  return K;
}

namespace {
// The incompatible-modes element's strain operators at the eight Gauss points: the displacements'
// B, the nine modes' Ba and det J.
struct IncompatibleOperators {
  std::array<Eigen::Matrix<double, 6, 24>, 8> B;
  std::array<Eigen::Matrix<double, 6, 9>, 8> Ba;
  std::array<double, 8> det;
};

IncompatibleOperators incompatible_operators(const HexCorners& X) {
  const Eigen::Matrix3d J0 = hex_jacobian(X, hex_parent_derivatives(Eigen::Vector3d::Zero()));
  const double det0 = checked_determinant(J0, -1);
  const Eigen::Matrix3d J0inv = J0.inverse();
  IncompatibleOperators o;
  for (int p = 0; p < 8; ++p) {
    const std::size_t i = static_cast<std::size_t>(p);
    const Eigen::Vector3d s = gauss_point(p);
    const Eigen::Matrix<double, 3, 8> dN = hex_parent_derivatives(s);
    const Eigen::Matrix3d J = hex_jacobian(X, dN);
    o.det[i] = checked_determinant(J, p);
    o.B[i] = strain_rows<8>(Eigen::Matrix<double, 3, 8>(J.inverse() * dN));
    // Modes 1 - s_k^2: parent gradient -2 s_k e_k, mapped with the centre's Jacobian and scaled
    // by det J0 / det J so that each mode's strain integrates to zero (Taylor's patch-test fix).
    Eigen::Matrix3d dP = Eigen::Matrix3d::Zero();
    for (int k = 0; k < 3; ++k) dP(k, k) = -2.0 * s(k);
    o.Ba[i] = strain_rows<3>(Eigen::Matrix3d(J0inv * dP * (det0 / o.det[i])));
  }
  return o;
}

// The incompatible-modes element's blocks for D, each linear in D: displacements (uu), their
// coupling to the nine modes (ua) and the modes' own (aa).
struct IncompatibleBlocks {
  HexMatrix uu = HexMatrix::Zero();
  Eigen::Matrix<double, 24, 9> ua = Eigen::Matrix<double, 24, 9>::Zero();
  Eigen::Matrix<double, 9, 9> aa = Eigen::Matrix<double, 9, 9>::Zero();
};

// With uu only where with_uu (the derivative's projection forms its own).
IncompatibleBlocks incompatible_blocks(const IncompatibleOperators& o, const Voigt6Matrix& D, bool with_uu = true) {
  IncompatibleBlocks k;
  for (std::size_t p = 0; p < 8; ++p) {
    const Eigen::Matrix<double, 6, 24>& B = o.B[p];
    const Eigen::Matrix<double, 6, 9>& Ba = o.Ba[p];
    const double det = o.det[p];
    if (with_uu) k.uu += B.transpose() * D * B * det;
    k.ua += B.transpose() * D * Ba * det;
    k.aa += Ba.transpose() * D * Ba * det;
  }
  return k;
}
}  // namespace

HexMatrix hex_incompatible_modes_stiffness(const HexCorners& X, const Voigt6Matrix& D) {
  const IncompatibleBlocks k = incompatible_blocks(incompatible_operators(X), D);
  return k.uu - k.ua * k.aa.ldlt().solve(k.ua.transpose());
}

std::vector<Eigen::Matrix<double, 12, 12>> hex_hourglass_stiffness_derivatives(const HexCorners& X, const Voigt6Matrix& D,
                                                                              const std::vector<Voigt6Matrix>& dD) {
  // K = Kuu - Kua Kaa^-1 Kua^T with every block linear in D, Kaa read from its lower triangle as
  // the LDL^T factorisation reads it (a consistent tangent with kinematic hardening is not
  // symmetric): dK = dKuu - dKua S - S^T dKua^T + S^T dKaa S, S = Kaa^-1 Kua^T, the same S for
  // every direction. Projected onto the hourglass shapes H point by point, with P = B H and
  // Q = Ba S H (6 x 12 each): H^T dK H = sum w (P^T d P - X - X^T) + (S H)^T L(dKaa) (S H),
  // X = P^T d Q, L reading the lower triangle -- products of 6 x 12 blocks instead of the full
  // 24 x 24 and 24 x 9 ones, and the points' operators formed once for every direction.
  struct Projected {
    Eigen::Matrix<double, 6, 12> P, Q;
  };
  const IncompatibleOperators o = incompatible_operators(X);
  const IncompatibleBlocks k = incompatible_blocks(o, D, false);
  const Eigen::Matrix<double, 24, 12> H = hex_hourglass_shapes();
  const Eigen::Matrix<double, 9, 12> SH = k.aa.ldlt().solve(k.ua.transpose()) * H;
  std::array<Projected, 8> points;
  for (std::size_t p = 0; p < 8; ++p) {
    points[p].P = o.B[p] * H;
    points[p].Q = o.Ba[p] * SH;
  }
  std::vector<Eigen::Matrix<double, 12, 12>> out;
  out.reserve(dD.size());
  for (const Voigt6Matrix& d : dD) {
    Eigen::Matrix<double, 12, 12> sum = Eigen::Matrix<double, 12, 12>::Zero(), cross = Eigen::Matrix<double, 12, 12>::Zero();
    Eigen::Matrix<double, 9, 9> daa = Eigen::Matrix<double, 9, 9>::Zero();
    for (std::size_t p = 0; p < 8; ++p) {
      const Projected& q = points[p];
      const Eigen::Matrix<double, 6, 12> dP = o.det[p] * (d * q.P), dQ = o.det[p] * (d * q.Q);
      sum.noalias() += q.P.transpose() * dP;
      cross.noalias() += q.P.transpose() * dQ;
      daa.noalias() += o.det[p] * (o.Ba[p].transpose() * d * o.Ba[p]);
    }
    const Eigen::Matrix<double, 9, 9> daa_lower = daa.selfadjointView<Eigen::Lower>();
    out.push_back(sum - cross - cross.transpose() + SH.transpose() * daa_lower * SH);
  }
  return out;
}

Eigen::Matrix<double, 12, 12> hex_hourglass_stiffness_derivative(const HexCorners& X, const Voigt6Matrix& D, const Voigt6Matrix& dD) {
  return hex_hourglass_stiffness_derivatives(X, D, {dD}).front();
}

Eigen::Matrix<double, 12, 12> hex_hourglass_stiffness(const HexCorners& X, const Voigt6Matrix& D) {
  const Eigen::Matrix<double, 24, 12> H = hex_hourglass_shapes();
  return H.transpose() * hex_incompatible_modes_stiffness(X, D) * H;
}

HexMatrix hex_stabilisation_stiffness(const HexCorners& X, const Voigt6Matrix& D) {
  const Eigen::Matrix<double, 12, 24> G = hex_hourglass_operator(X, hex_uniform_gradient(X));
  const Eigen::Matrix<double, 12, 12> Kq = hex_hourglass_stiffness(X, D);
  return G.transpose() * Kq * G;
}

}  // namespace spifit::element
