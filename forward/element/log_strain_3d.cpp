#include "forward/element/log_strain_3d.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>

namespace spifit::element {
namespace {

using Mat3 = Eigen::Matrix3d;

// atanh(x) / x = sum_k x^(2k) / (2k + 1); the series below |x| = 0.1, where the closed form
// cancels: ten terms leave less than 0.01^10 / 21 = 5e-22.
double atanh_ratio(double x) {
  const double y = x * x;
  if (y < 1e-2) {
    double f = 0.0;
    for (int k = 10; k >= 0; --k) f = 1.0 / (2.0 * k + 1.0) + y * f;
    return f;
  }
  return 0.5 * std::log((1.0 + x) / (1.0 - x)) / x;
}

// The symmetric tensor of a Voigt vector with engineering shears.
Mat3 tensor_of_strain(const Voigt6& v) {
  Mat3 t;
  t << v(0), 0.5 * v(3), 0.5 * v(4), 0.5 * v(3), v(1), 0.5 * v(5), 0.5 * v(4), 0.5 * v(5), v(2);
  return t;
}
Mat3 tensor_of_stress(const Voigt6& v) {
  Mat3 t;
  t << v(0), v(3), v(4), v(3), v(1), v(5), v(4), v(5), v(2);
  return t;
}
Voigt6 strain_of_tensor(const Mat3& t) {
  Voigt6 v;
  v << t(0, 0), t(1, 1), t(2, 2), 2.0 * t(0, 1), 2.0 * t(0, 2), 2.0 * t(1, 2);
  return v;
}

// Index pairs of the Voigt components.
constexpr int kRow[6] = {0, 1, 2, 0, 0, 1};
constexpr int kCol[6] = {0, 1, 2, 1, 2, 2};

// The unit Green strain of Voigt component b as a tensor, in the eigenbasis Q.
std::array<Mat3, 6> unit_strains_in_basis(const Mat3& Q) {
  std::array<Mat3, 6> out;
  for (int b = 0; b < 6; ++b) {
    Mat3 B = Mat3::Zero();
    if (b < 3) {
      B(b, b) = 1.0;
    } else {
      B(kRow[b], kCol[b]) = 0.5;
      B(kCol[b], kRow[b]) = 0.5;
    }
    out[static_cast<std::size_t>(b)] = Q.transpose() * B * Q;
  }
  return out;
}

struct Eigen3 {
  Mat3 Q;
  Eigen::Vector3d mu;      // eigenvalues of E
  Eigen::Vector3d lambda;  // 1 + 2 mu, eigenvalues of C
};

Eigen3 decompose(const Voigt6& green) {
  // The eigenvalues of E, not of C: ln(1 + 2 mu) then keeps the digits of small strains.
  const Eigen::SelfAdjointEigenSolver<Mat3> es(tensor_of_strain(green));
  Eigen3 d;
  d.Q = es.eigenvectors();
  d.mu = es.eigenvalues();
  d.lambda = (Eigen::Vector3d::Ones() + 2.0 * d.mu);
  return d;
}

Voigt6 value_from(const Eigen3& d) {
  Eigen::Vector3d half_log;
  for (int i = 0; i < 3; ++i) half_log(i) = 0.5 * std::log1p(2.0 * d.mu(i));
  return strain_of_tensor(d.Q * half_log.asDiagonal() * d.Q.transpose());
}

}  // namespace

double log_divided_difference(double a, double b) {
  const double s = a + b;
  return 2.0 * atanh_ratio((a - b) / s) / s;
}

double log_divided_difference(double a, double b, double c) {
  // Symmetric in its arguments: sort so that a >= b >= c.
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  const double m = (a + b + c) / 3.0;
  if (a - c > 0.05 * m) return (log_divided_difference(a, b) - log_divided_difference(b, c)) / (a - c);
  // ln(m + d) = ln m + sum_k (-1)^(k+1) d^k / (k m^k), and the second divided difference of d^k
  // over (da, db, dc) is h_(k-2)(da, db, dc), the complete homogeneous symmetric polynomial.
  // |d| <= 0.05 m: the terms past k = 18 are below 1e-18 of the first.
  const double da = (a - m) / m, db = (b - m) / m, dc = (c - m) / m;
  double h1 = 1.0, h2 = 1.0, h3 = 1.0;  // h_j of (da), (da, db), (da, db, dc) at j = 0
  double sum = -0.5;                     // k = 2: (-1)^3 h_0 / 2
  for (int k = 3; k <= 18; ++k) {
    h1 *= da;
    h2 = db * h2 + h1;
    h3 = dc * h3 + h2;
    sum += ((k % 2 == 1) ? 1.0 : -1.0) * h3 / k;
  }
  return sum / (m * m);
}

Voigt6 log_strain_3d_value(const Voigt6& green) { return value_from(decompose(green)); }

LogStrain3 log_strain_3d(const Voigt6& green) {
  const Eigen3 d = decompose(green);
  LogStrain3 out;
  out.value = value_from(d);
  out.basis = d.Q;
  out.lambda = d.lambda;
  Mat3 f1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) f1(i, j) = log_divided_difference(d.lambda(i), d.lambda(j));
  out.units = unit_strains_in_basis(d.Q);
  const auto& units = out.units;
  for (int b = 0; b < 6; ++b) {
    // d eps = D(ln C / 2)[2 dE] = D ln(C)[dE]
    const Mat3 de = d.Q * f1.cwiseProduct(units[static_cast<std::size_t>(b)]) * d.Q.transpose();
    out.first.col(b) = strain_of_tensor(de);
  }
  return out;
}

Voigt6x6 log_strain_3d_second(const LogStrain3& ls, const Voigt6& T) {
  // ln[a, b, c] sorts its arguments: one evaluation per multiset of indices (10 of the 27).
  double f2[3][3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = i; k < 3; ++k)
      for (int j = k; j < 3; ++j) {
        const double v = log_divided_difference(ls.lambda(i), ls.lambda(k), ls.lambda(j));
        f2[i][k][j] = f2[i][j][k] = f2[k][i][j] = f2[k][j][i] = f2[j][i][k] = f2[j][k][i] = v;
      }
  const Mat3 t = ls.basis.transpose() * tensor_of_stress(T) * ls.basis;
  const auto& units = ls.units;
  // W(b, c) = sum_ijk f2_ikj t_ij A_ik B_kj with A, B the unit strains b, c; then
  // T : d2 eps[b, c] = 2 T : D2 ln(C)[b, c] = 2 (W(b, c) + W(c, b)).
  Voigt6x6 W;
  for (int b = 0; b < 6; ++b) {
    const Mat3& A = units[static_cast<std::size_t>(b)];
    // P_kj = sum_i f2_ikj t_ij A_ik, so that W(b, c) = sum_kj P_kj B_kj.
    Mat3 P = Mat3::Zero();
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) P(k, j) += f2[i][k][j] * t(i, j) * A(i, k);
    for (int c = 0; c < 6; ++c) W(b, c) = P.cwiseProduct(units[static_cast<std::size_t>(c)]).sum();
  }
  return 2.0 * (W + W.transpose());
}

}  // namespace spifit::element
