// The relative offset convergence criterion (inverse/fit/relative_offset.hpp) on linear models
// whose Gauss-Newton step and standard errors are known in closed form.
#include "inverse/fit/relative_offset.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>

using spifit::inverse::relative_offset;

// One parameter, four residuals r = (1, -1, 1, -1) + c (1, 1, 1, 1): the tangent plane is the
// direction (1, 1, 1, 1) / 2, so |Q1^T r| = 2c and |Q2^T r|^2 = 4; offset = 2c / sqrt(4 / 3).
// The step -c and the standard error sqrt(4/3) / 2 give |step| / sigma = sqrt(3) c as well: for
// one parameter the bound is reached.
TEST(RelativeOffset, ClosedFormForAMean) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Ones(4, 1);
  const double c = 0.1;
  Eigen::VectorXd r(4);
  r << 1 + c, -1 + c, 1 + c, -1 + c;
  const auto o = relative_offset(J, r);
  EXPECT_EQ(o.rank, 1);
  EXPECT_NEAR(o.offset, std::sqrt(3.0) * c, 1e-15);
  EXPECT_NEAR(o.step_bound(), c / (std::sqrt(4.0 / 3.0) / 2.0), 1e-15);
  // Scaling the column (another unit, a log-scaled coordinate) changes nothing.
  EXPECT_NEAR(relative_offset(J * 250.0, r).offset, o.offset, 1e-15);
}

// Three parameters of a 12-point linear model, away from the least-squares solution: every
// component of the Gauss-Newton step lies within step_bound() standard errors, and at the
// solution the offset vanishes (to round-off).
TEST(RelativeOffset, BoundsTheGaussNewtonStepInStandardErrors) {
  const int m = 12, p = 3;
  Eigen::MatrixXd J(m, p);
  Eigen::VectorXd y(m);
  for (int i = 0; i < m; ++i) {
    const double t = 0.25 * i;
    J(i, 0) = 1.0;
    J(i, 1) = t;
    J(i, 2) = 40.0 * std::sin(t);          // a column of another scale
    y(i) = 2.0 + 0.3 * t + std::cos(3.1 * t);  // not in the model: a real residual scatter
  }
  const Eigen::VectorXd x_star = J.colPivHouseholderQr().solve(y);
  const Eigen::VectorXd x = x_star + Eigen::Vector3d(0.15, -0.06, 0.003);
  const Eigen::VectorXd r = J * x - y;
  const auto o = relative_offset(J, r);
  ASSERT_EQ(o.rank, p);
  ASSERT_TRUE(std::isfinite(o.offset));
  const Eigen::VectorXd step = x_star - x;
  const Eigen::VectorXd r_star = J * x_star - y;
  const double s2 = r_star.squaredNorm() / (m - p);
  const Eigen::MatrixXd cov = s2 * (J.transpose() * J).inverse();
  double worst = 0.0;
  for (int k = 0; k < p; ++k) worst = std::max(worst, std::abs(step(k)) / std::sqrt(cov(k, k)));
  EXPECT_GT(worst, 0.1);  // the point is off by a visible part of a standard error
  EXPECT_LE(worst, o.step_bound() * (1 + 1e-12));
  EXPECT_LT(relative_offset(J, r_star).offset, 1e-12);
}

// Where it says nothing: as many residuals as parameters, data the model fits exactly, residuals
// of round-off size, non-finite entries.
TEST(RelativeOffset, UndefinedWithoutResidualScatter) {
  Eigen::MatrixXd J(2, 2);
  J << 1, 0, 0, 1;
  EXPECT_TRUE(std::isnan(relative_offset(J, Eigen::Vector2d(0.1, 0.2)).offset));
  Eigen::MatrixXd K = Eigen::MatrixXd::Ones(3, 1);
  EXPECT_TRUE(std::isnan(relative_offset(K, Eigen::Vector3d(0.5, 0.5, 0.5)).offset));
  // Residuals that are round-off (a noise-free fit at its solution): both parts are noise.
  Eigen::MatrixXd L(4, 1);
  L << 1, 2, 3, 4;
  EXPECT_TRUE(std::isnan(relative_offset(L, Eigen::Vector4d(3e-9, -1e-9, 2e-9, 1e-9)).offset));
  EXPECT_TRUE(std::isfinite(relative_offset(L, Eigen::Vector4d(3e-3, -1e-3, 2e-3, 1e-3)).offset));
  Eigen::MatrixXd bad = Eigen::MatrixXd::Ones(3, 1);
  bad(1, 0) = std::nan("");
  EXPECT_TRUE(std::isnan(relative_offset(bad, Eigen::Vector3d(0.5, 0.1, 0.5)).offset));
}
