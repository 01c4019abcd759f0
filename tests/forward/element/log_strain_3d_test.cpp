#include "forward/element/log_strain_3d.hpp"

#include "forward/element/log_strain.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace spifit::element {
namespace {

Voigt6 voigt(const Eigen::Matrix3d& t) {
  Voigt6 v;
  v << t(0, 0), t(1, 1), t(2, 2), 2.0 * t(0, 1), 2.0 * t(0, 2), 2.0 * t(1, 2);
  return v;
}
Eigen::Matrix3d rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()) * Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitZ())).toRotationMatrix();
}

TEST(LogStrain3d, DividedDifferencesOfTheLogarithm) {
  EXPECT_NEAR(log_divided_difference(2.0, 0.5), (std::log(2.0) - std::log(0.5)) / 1.5, 1e-15);
  EXPECT_DOUBLE_EQ(log_divided_difference(1.3, 1.3), 1.0 / 1.3);
  // Second differences: closed form (well separated), the limit -1/(2a^2), and the two branches
  // meeting at the switch (a - c = 0.05 m) without a jump.
  const double a = 1.9, b = 1.2, c = 0.6;
  const double closed = ((std::log(a) - std::log(b)) / (a - b) - (std::log(b) - std::log(c)) / (b - c)) / (a - c);
  EXPECT_NEAR(log_divided_difference(a, b, c), closed, 1e-15);
  EXPECT_NEAR(log_divided_difference(c, a, b), closed, 1e-15);
  EXPECT_NEAR(log_divided_difference(0.8, 0.8, 0.8), -1.0 / (2.0 * 0.64), 1e-15);
  const double m = 1.1, r0 = 0.025 - 1e-13, r1 = 0.025 + 1e-13;
  const double below = log_divided_difference(m + r0 * m, m, m - r0 * m), above = log_divided_difference(m + r1 * m, m, m - r1 * m);
  EXPECT_NEAR(below, above, 1e-13 * std::abs(below));
  // Near-equal arguments: the series against the closed form in long double.
  const long double la = 1.0L + 1e-3L, lb = 1.0L, lc = 1.0L - 2e-3L;
  const long double ref = ((std::log(la) - std::log(lb)) / (la - lb) - (std::log(lb) - std::log(lc)) / (lb - lc)) / (la - lc);
  EXPECT_NEAR(log_divided_difference(1.001, 1.0, 0.998), static_cast<double>(ref), 1e-9);
}

TEST(LogStrain3d, ValueIsTheRotatedLogarithmOfTheStretches) {
  const Eigen::Matrix3d R = rotation();
  const Eigen::Vector3d l(1.6, 0.7, 1.05);  // principal stretches
  const Eigen::Matrix3d E = 0.5 * (R * l.cwiseAbs2().asDiagonal() * R.transpose() - Eigen::Matrix3d::Identity());
  const Eigen::Matrix3d expected = R * Eigen::Vector3d(std::log(l(0)), std::log(l(1)), std::log(l(2))).asDiagonal() * R.transpose();
  EXPECT_LT((log_strain_3d_value(voigt(E)) - voigt(expected)).cwiseAbs().maxCoeff(), 1e-15);
  // Small strains keep their digits: eps = E - E^2 + ... for E = 1e-9.
  Voigt6 tiny;
  tiny << 1e-9, -2e-9, 0.5e-9, 1e-9, 0.0, -1e-9;
  EXPECT_LT((log_strain_3d_value(tiny) - tiny).cwiseAbs().maxCoeff(), 1e-17);
}

TEST(LogStrain3d, PlaneStrainsMatchTheShellsTwoDimensionalLogarithm) {
  Voigt6 green;
  green << 0.3, -0.1, 0.0, 0.25, 0.0, 0.0;
  const Eigen::Vector3d plane(0.3, -0.1, 0.25);
  const Eigen::Vector3d e2 = log_strain_value(plane);
  const LogStrain3 e3 = log_strain_3d(green);
  EXPECT_NEAR(e3.value(0), e2(0), 1e-15);
  EXPECT_NEAR(e3.value(1), e2(1), 1e-15);
  EXPECT_NEAR(e3.value(3), e2(2), 1e-15);
  EXPECT_NEAR(e3.value(2), 0.0, 1e-16);
  const LogStrain d2 = log_strain_with_derivatives(plane, true);
  const int idx[3] = {0, 1, 3};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(e3.first(idx[i], idx[j]), d2.first(i, j), 1e-14) << i << " " << j;
}

// First and contracted second derivatives against central differences (step 1e-6: truncation
// ~1e-12, round-off ~1e-10 of the values).
void check_derivatives(const Voigt6& green, const char* where) {
  SCOPED_TRACE(where);
  const LogStrain3 d = log_strain_3d(green);
  Voigt6 T;
  T << 120.0, -40.0, 15.0, 60.0, -25.0, 33.0;
  const Voigt6x6 L = log_strain_3d_second(d, T);
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Voigt6 gp = green, gm = green;
    gp(j) += h;
    gm(j) -= h;
    const Voigt6 fd = (log_strain_3d_value(gp) - log_strain_3d_value(gm)) / (2.0 * h);
    EXPECT_LT((fd - d.first.col(j)).cwiseAbs().maxCoeff(), 2e-9) << "first, column " << j;
    const Voigt6 sfd = (log_strain_3d(gp).first.transpose() * T - log_strain_3d(gm).first.transpose() * T) / (2.0 * h);
    EXPECT_LT((sfd - L.col(j)).cwiseAbs().maxCoeff(), 2e-7 * T.norm()) << "second, column " << j;
  }
  EXPECT_LT((L - L.transpose()).cwiseAbs().maxCoeff(), 1e-12 * T.norm());
}

TEST(LogStrain3d, DerivativesMatchCentralDifferences) {
  Voigt6 general;
  general << 0.35, -0.12, 0.05, 0.3, -0.2, 0.15;
  check_derivatives(general, "distinct eigenvalues");
  check_derivatives(Voigt6::Zero(), "C = I (threefold eigenvalue)");
  const Eigen::Matrix3d R = rotation();
  const Eigen::Matrix3d twofold = R * Eigen::Vector3d(0.2, 0.2, -0.15).asDiagonal() * R.transpose();
  check_derivatives(voigt(twofold), "twofold eigenvalue, rotated");
  const Eigen::Matrix3d close = R * Eigen::Vector3d(0.2, 0.2 + 1e-9, -0.15).asDiagonal() * R.transpose();
  check_derivatives(voigt(close), "nearly twofold eigenvalue, rotated");
  // At C = I the derivative is the identity.
  EXPECT_LT((log_strain_3d(Voigt6::Zero()).first - Voigt6x6::Identity()).cwiseAbs().maxCoeff(), 1e-15);
}

}  // namespace
}  // namespace spifit::element
