// Uncertainty analysis on problems with known answers.
#include "inverse/uncertainty/uncertainty.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>

using namespace spifit::inverse;

// Published t quantiles (two-sided 95 %): 12.706 (1 dof), 2.228 (10), 1.984 (100).
TEST(Uncertainty, StudentTQuantiles) {
  EXPECT_NEAR(student_t_quantile(0.975, 1), 12.7062, 1e-3);
  EXPECT_NEAR(student_t_quantile(0.975, 10), 2.2281, 1e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 100), 1.9840, 1e-4);
}

// Straight line y = a + b x through 5 points: covariance s^2 (X^T X)^-1 in closed form.
TEST(Uncertainty, LinearRegression) {
  Eigen::MatrixXd J(5, 2);
  Eigen::VectorXd r(5);
  for (int i = 0; i < 5; ++i) { J(i, 0) = 1.0; J(i, 1) = i; }
  r << 0.1, -0.2, 0.05, 0.1, -0.05;
  const auto u = analyse_uncertainty(J, r, {1.0, 2.0}, {"a", "b"});
  const double s2 = r.squaredNorm() / 3.0;
  const Eigen::Matrix2d cov = s2 * (J.transpose() * J).inverse();
  EXPECT_NEAR(u.std_error[0], std::sqrt(cov(0, 0)), 1e-12);
  EXPECT_NEAR(u.std_error[1], std::sqrt(cov(1, 1)), 1e-12);
  EXPECT_NEAR(u.correlation(0, 1), cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 1e-12);
  EXPECT_TRUE(u.warnings.empty());
}

// Correlation does not depend on sigma^2: an exact fit (zero residuals) keeps it.
TEST(Uncertainty, CorrelationWithZeroResiduals) {
  Eigen::MatrixXd J(5, 2);
  for (int i = 0; i < 5; ++i) { J(i, 0) = 1.0; J(i, 1) = i; }
  const auto u = analyse_uncertainty(J, Eigen::VectorXd::Zero(5), {1.0, 2.0}, {"a", "b"});
  const Eigen::Matrix2d c = (J.transpose() * J).inverse();
  EXPECT_NEAR(u.correlation(0, 1), c(0, 1) / std::sqrt(c(0, 0) * c(1, 1)), 1e-12);
}

// A single parameter whose effect is far below the noise is not identifiable (absolute floor).
TEST(Uncertainty, NegligibleSensitivityIsNotIdentifiable) {
  Eigen::MatrixXd J(4, 1);
  J << 1e-13, 2e-13, -1e-13, 0.5e-13;
  const auto u = analyse_uncertainty(J, Eigen::VectorXd::Constant(4, 0.5), {1.0}, {"g"});
  EXPECT_FALSE(u.identifiable[0]);
  EXPECT_FALSE(std::isfinite(u.std_error[0]));
}

// Two parameters that only appear as a sum: rank deficient, both reported, nothing crashes.
TEST(Uncertainty, RankDeficient) {
  Eigen::MatrixXd J(4, 3);
  J << 1, 1, 0.5, 2, 2, 0.1, 3, 3, 0.7, 4, 4, 0.2;
  Eigen::VectorXd r = Eigen::VectorXd::Constant(4, 0.01);
  const auto u = analyse_uncertainty(J, r, {1.0, 1.0, 1.0}, {"a", "b", "c"});
  EXPECT_FALSE(u.identifiable[0]);
  EXPECT_FALSE(u.identifiable[1]);
  EXPECT_TRUE(u.identifiable[2]);
  EXPECT_EQ(u.warnings.size(), 2u);
}

// Fisher information per block of rows: block 0 = row 0, block 1 = rows 1-2. Column a: 1 of
// 1 + 4 + 0 = 5 in block 0; column b: none in block 0; column c: no row responds (NaN).
TEST(Uncertainty, InformationSharesPerBlockOfRows) {
  Eigen::MatrixXd J(3, 3);
  J << 1.0, 0.0, 0.0,
       2.0, 1.0, 0.0,
       0.0, -3.0, 0.0;
  const Eigen::MatrixXd s = information_shares(J, {1, 2});
  ASSERT_EQ(s.rows(), 2);
  ASSERT_EQ(s.cols(), 3);
  EXPECT_DOUBLE_EQ(s(0, 0), 0.2);
  EXPECT_DOUBLE_EQ(s(1, 0), 0.8);
  EXPECT_EQ(s(0, 1), 0.0);
  EXPECT_EQ(s(1, 1), 1.0);
  EXPECT_TRUE(std::isnan(s(0, 2)));
  EXPECT_TRUE(std::isnan(s(1, 2)));
  // Scaling a column (another unit of the parameter) leaves its shares alone.
  J.col(0) *= 1e3;
  EXPECT_DOUBLE_EQ(information_shares(J, {1, 2})(0, 0), 0.2);
}
