#include "forward/element/log_strain.hpp"
#include "forward/element/thickness_rule.hpp"

#include <ceres/jet.h>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace spifit::element {
namespace {

// ln(C)/2 from the eigen-decomposition (reference for the closed form).
Eigen::Vector3d log_strain_by_eigen(const Eigen::Vector3d& g) {
  Eigen::Matrix2d c;
  c << 1.0 + 2.0 * g(0), g(2), g(2), 1.0 + 2.0 * g(1);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(c);
  const Eigen::Matrix2d l = es.eigenvectors() * es.eigenvalues().array().log().matrix().asDiagonal() *
                            es.eigenvectors().transpose() * 0.5;
  return {l(0, 0), l(1, 1), 2.0 * l(0, 1)};
}

TEST(LogStrain, MatchesEigenDecompositionFromSmallToFourHundredPercent) {
  const Eigen::Vector3d cases[] = {{1e-9, -2e-9, 3e-9}, {0.01, 0.01, 0.0}, {0.01, 0.0101, 1e-4},
                                   {4.2, -0.1, 0.3},    {-0.3, 0.5, -0.4}, {2.0, 2.0, 0.0}};
  for (const auto& g : cases) {
    const Eigen::Vector3d a = log_strain_of_green(g), b = log_strain_by_eigen(g);
    EXPECT_LT((a - b).norm(), 1e-14 * (1.0 + b.norm())) << g.transpose();
  }
  // Uniaxial stretch 3.07 (thesis: 420 % Green radial strain) is log strain 1.12.
  const double lambda = 3.07;
  EXPECT_NEAR(log_strain_of_green(Eigen::Vector3d(0.5 * (lambda * lambda - 1.0), 0.0, 0.0))(0), std::log(lambda), 1e-14);
}

// Value, first and second derivatives by nested forward-mode Jets through the generic template
// (the implementation before the closed form; the reference for it).
LogStrain log_strain_by_nested_jets(const Eigen::Vector3d& green) {
  using Inner = ceres::Jet<double, 3>;
  using Outer = ceres::Jet<Inner, 3>;
  Eigen::Matrix<Outer, 3, 1> g;
  for (int j = 0; j < 3; ++j) g(j) = Outer(Inner(green(j), j), j);
  const Eigen::Matrix<Outer, 3, 1> eps = log_strain_of_green(g);
  LogStrain out;
  for (int i = 0; i < 3; ++i) {
    out.value(i) = eps(i).a.a;
    for (int j = 0; j < 3; ++j) {
      out.first(i, j) = eps(i).a.v(j);
      for (int k = 0; k < 3; ++k) out.second[static_cast<std::size_t>(i)](j, k) = eps(i).v(j).v(k);
    }
  }
  return out;
}

TEST(LogStrain, ClosedFormDerivativesMatchNestedJets) {
  // y = 1 - det C / m^2 spans 0 (equal eigenvalues), both sides of the series switch at 0.05,
  // and a 400 % stretch with compression (y near 1).
  const Eigen::Vector3d points[] = {{0.0, 0.0, 0.0},   {1e-9, -2e-9, 3e-9}, {0.02, 0.0199, 1e-5}, {0.2, 0.0, 0.0},
                                    {0.25, 0.0, 0.0},  {0.3, -0.05, 0.01},  {1.5, -0.2, 0.4},     {0.1, 0.3, -0.25},
                                    {4.2, -0.3, 0.3},  {-0.3, 0.5, -0.4},   {2.0, 2.0, 0.0},      {-0.2, -0.2, 0.1}};
  for (const auto& g : points) {
    const LogStrain c = log_strain_with_derivatives(g), j = log_strain_by_nested_jets(g);
    EXPECT_LT((c.value - j.value).norm(), 1e-14 * (1.0 + j.value.norm())) << g.transpose();
    EXPECT_LT((c.first - j.first).norm(), 1e-13 * (1.0 + j.first.norm())) << g.transpose();
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_LT((c.second[i] - j.second[i]).norm(), 1e-12 * (1.0 + j.second[i].norm())) << "component " << i << " at " << g.transpose();
  }
}

TEST(LogStrain, DerivativesMatchCentralDifferences) {
  const Eigen::Vector3d points[] = {{0.0, 0.0, 0.0}, {0.02, 0.0199, 1e-5}, {1.5, -0.2, 0.4}, {0.1, 0.3, -0.25}};
  for (const auto& g : points) {
    const LogStrain ls = log_strain_with_derivatives(g);
    EXPECT_LT((ls.value - log_strain_by_eigen(g)).norm(), 1e-13);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d gp = g, gm = g;
      gp(j) += h;
      gm(j) -= h;
      const Eigen::Vector3d fd = (log_strain_of_green(gp) - log_strain_of_green(gm)) / (2.0 * h);
      EXPECT_LT((fd - ls.first.col(j)).norm(), 1e-8) << "first derivative, column " << j << " at " << g.transpose();
      const LogStrain lp = log_strain_with_derivatives(gp), lm = log_strain_with_derivatives(gm);
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d fd2 = (lp.first.row(i) - lm.first.row(i)).transpose() / (2.0 * h);
        EXPECT_LT((fd2 - ls.second[static_cast<std::size_t>(i)].col(j)).norm(), 1e-6)
            << "second derivative " << i << "," << j << " at " << g.transpose();
      }
    }
  }
}

// The section's commit re-evaluates the layers' log strains with log_strain_value; the next
// update subtracts them from log_strain_with_derivatives' values, so the two must agree bit for
// bit (else a zero strain increment shows as round-off), on every branch of the series (y below
// 1e-6, 1e-3, 0.05) and of the closed form.
TEST(LogStrain, ValueAloneIsBitForBitThatOfTheDerivatives) {
  const Eigen::Vector3d greens[] = {{0.0, 0.0, 0.0},     {1e-5, -3e-6, 2e-6}, {0.01, 0.004, -0.003}, {0.05, -0.02, 0.03},
                                    {0.3, -0.1, 0.2},    {2.0, 0.5, -0.7},    {-0.2, -0.2, 0.0},     {1e-9, 1e-9, 1e-12}};
  for (const Eigen::Vector3d& g : greens) {
    const Eigen::Vector3d v = spifit::element::log_strain_value(g);
    for (bool second : {false, true}) {
      const Eigen::Vector3d w = spifit::element::log_strain_with_derivatives(g, second).value;
      for (int i = 0; i < 3; ++i) EXPECT_EQ(v(i), w(i)) << "E = " << g.transpose() << ", component " << i;
    }
  }
}

TEST(ThicknessRule, GaussLegendreIsExactToDegreeTwoNMinusOne) {
  for (int n = 1; n <= 11; ++n) {
    const ThicknessRule r = gauss_legendre_rule(n);
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      double s = 0.0;
      for (std::size_t i = 0; i < r.zeta.size(); ++i) s += r.weight[i] * std::pow(r.zeta[i], degree);
      const double exact = degree % 2 == 1 ? 0.0 : 2.0 / (degree + 1.0);
      EXPECT_NEAR(s, exact, 1e-14) << n << " points, degree " << degree;
    }
  }
  EXPECT_THROW(gauss_legendre_rule(0), std::invalid_argument);
  EXPECT_THROW(gauss_legendre_rule(12), std::invalid_argument);
}

TEST(ThicknessRule, FullyPlasticMomentIsUnderIntegrated) {
  // integral of |zeta| over [-1, 1] is 1: the plastic moment in units of sigma_y h^2 / 4.
  auto plastic = [](int n) {
    const ThicknessRule r = gauss_legendre_rule(n);
    double s = 0.0;
    for (std::size_t i = 0; i < r.zeta.size(); ++i) s += r.weight[i] * std::abs(r.zeta[i]);
    return s;
  };
  // docs/design/numerics-shell.md, "Known limits": 5 points miss ~5 %.
  EXPECT_NEAR(plastic(5), 0.944850, 1e-6);
  EXPECT_NEAR(plastic(11), 0.987523, 1e-6);  // still 1.25 % short
}

TEST(ThicknessRule, SurfaceRuleHasSurfaceAndMidPointsAndIntegratesBendingExactly) {
  for (int n = 3; n <= 11; n += 2) {
    const ThicknessRule r = make_thickness_rule(ThicknessRuleKind::surface, n);
    ASSERT_EQ(static_cast<int>(r.zeta.size()), n);
    EXPECT_DOUBLE_EQ(r.zeta.front(), -1.0);
    EXPECT_DOUBLE_EQ(r.zeta.back(), 1.0);
    EXPECT_NEAR(r.zeta[static_cast<std::size_t>(n / 2)], 0.0, 1e-15);
    const int m = (n + 1) / 2;  // Lobatto points per half: exact to degree 2m - 3 on each half
    double plastic = 0.0;
    for (std::size_t i = 0; i < r.zeta.size(); ++i) plastic += r.weight[i] * std::abs(r.zeta[i]);
    EXPECT_NEAR(plastic, 1.0, 1e-14) << n;  // the fully plastic moment, exactly
    for (int degree = 0; degree <= 2 * m - 3; ++degree) {
      double s = 0.0;
      for (std::size_t i = 0; i < r.zeta.size(); ++i) s += r.weight[i] * std::pow(r.zeta[i], degree);
      EXPECT_NEAR(s, degree % 2 == 1 ? 0.0 : 2.0 / (degree + 1.0), 1e-14) << n << " points, degree " << degree;
    }
  }
  // 5 points = Simpson's rule on each half: weights (1, 4, 2, 4, 1) / 6.
  const ThicknessRule simpson = make_thickness_rule(ThicknessRuleKind::surface, 5);
  const double expected[5] = {1.0 / 6.0, 4.0 / 6.0, 2.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(simpson.weight[static_cast<std::size_t>(i)], expected[i], 1e-15);
  EXPECT_THROW(make_thickness_rule(ThicknessRuleKind::surface, 4), std::invalid_argument);
  EXPECT_THROW(make_thickness_rule(ThicknessRuleKind::surface, 1), std::invalid_argument);
  EXPECT_THROW(make_thickness_rule(ThicknessRuleKind::surface, 13), std::invalid_argument);
}

}  // namespace
}  // namespace spifit::element
