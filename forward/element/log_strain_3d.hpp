#pragma once
// Lagrangian logarithmic (Hencky) strain of a 3D material point and its first and second
// derivatives with respect to the Green-Lagrange strain (docs/design/numerics-solid.md,
// "Large strain").
//
// eps = ln(C) / 2 with C = I + 2E the right Cauchy-Green tensor: the logarithm of the right
// stretch U, i.e. the Hencky strain seen in the frame that rotates with the material (the
// polar rotation R of F = R U). A law working on eps in fixed material axes is therefore
// corotational, and the additive split eps = eps_e + eps_p holds the small-strain return
// mapping unchanged (Miehe, Apel & Lambrecht 2002).
//
// With E = Q diag(mu) Q^T and lambda = 1 + 2 mu the eigenvalues of C, every derivative is a
// divided difference of ln in the eigenbasis (Daleckii-Krein):
//   d eps [dE]           = Q (F1 o (Q^T dE Q)) Q^T,            F1_ij = ln[lambda_i, lambda_j]
//   d2 eps [dE_a, dE_b]  = 2 Q M Q^T,  M_ij = sum_k ln[lambda_i, lambda_k, lambda_j]
//                                              (A_ik B_kj + B_ik A_kj),  A, B = Q^T dE_{a,b} Q.
// The divided differences are evaluated without cancellation (atanh form, series for nearly
// equal eigenvalues), so the derivatives are smooth through repeated eigenvalues, where the
// eigenvectors themselves are not defined: C = I at the start of every run is such a point.
// Voigt order xx, yy, zz, xy, xz, yz with engineering shears for E and eps
// (material/stress_space.hpp, Dim = 6), so that T . d eps is the work density.
#include <Eigen/Core>

#include <array>

namespace spifit::element {

using Voigt6 = Eigen::Matrix<double, 6, 1>;
using Voigt6x6 = Eigen::Matrix<double, 6, 6>;

struct LogStrain3 {
  Voigt6 value;      // eps
  Voigt6x6 first;    // d eps_i / d E_j
  // The eigenbasis of E, the eigenvalues of C and the unit Green strains of the six Voigt
  // components in that basis, kept for log_strain_3d_second.
  Eigen::Matrix3d basis;
  Eigen::Vector3d lambda;
  std::array<Eigen::Matrix3d, 6> units;
};

// Value and first derivative. Requires C positive definite (the callers check det F > 0).
LogStrain3 log_strain_3d(const Voigt6& green);
// The value alone, bit for bit that of log_strain_3d.
Voigt6 log_strain_3d_value(const Voigt6& green);
// sum_i T_i d2 eps_i / dE_j dE_k at the strain of `ls` (log_strain_3d's result, whose
// eigenbasis it reuses): the geometric part of the tangent of S = (d eps / dE)^T T.
Voigt6x6 log_strain_3d_second(const LogStrain3& ls, const Voigt6& T);

// ln[a, b] and ln[a, b, c]: the first and second divided differences of the natural logarithm
// (exposed for the tests).
double log_divided_difference(double a, double b);
double log_divided_difference(double a, double b, double c);

}  // namespace spifit::element
