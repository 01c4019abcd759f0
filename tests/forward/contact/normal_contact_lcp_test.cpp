// The frictionless MST contact problem solved by active sets, against every set tried in turn.
#include "forward/contact/normal_contact_lcp.hpp"

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include <random>

namespace spifit::contact {
namespace {

// The complementarity conditions: P >= 0, w = M P + q >= -tol, P_i w_i ~ 0.
void expect_complementary(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, const Eigen::VectorXd& P, double tol) {
  const Eigen::VectorXd w = M * P + q;
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    EXPECT_GE(P(i), 0.0) << i;
    EXPECT_GE(w(i), -tol) << i;
    EXPECT_LE(std::abs(P(i) * w(i)), tol * (1.0 + P.cwiseAbs().maxCoeff())) << i;
  }
}

// The solution by enumeration: the set whose forces are positive and leave no negative gap.
Eigen::VectorXd by_enumeration(const Eigen::MatrixXd& M, const Eigen::VectorXd& q) {
  const int k = static_cast<int>(q.size());
  for (int mask = 0; mask < (1 << k); ++mask) {
    std::vector<Eigen::Index> on;
    for (int i = 0; i < k; ++i)
      if (mask & (1 << i)) on.push_back(i);
    Eigen::VectorXd P = Eigen::VectorXd::Zero(k);
    if (!on.empty()) {
      const Eigen::MatrixXd A = M(on, on);
      const Eigen::VectorXd b = -q(on);
      const Eigen::VectorXd z = A.llt().solve(b);
      P(on) = z;
    }
    const Eigen::VectorXd w = M * P + q;
    if (P.minCoeff() >= 0.0 && w.minCoeff() >= -1e-12) return P;
  }
  return Eigen::VectorXd::Constant(k, -1.0);
}

TEST(NormalContactLcp, MatchesTheEnumeratedSolutionOnRandomPositiveDefiniteProblems) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int k = 1 + trial % 8;
    Eigen::MatrixXd B(k, k);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) B(i, j) = u(rng);
    const Eigen::MatrixXd M = B * B.transpose() + 0.1 * Eigen::MatrixXd::Identity(k, k);
    Eigen::VectorXd q(k);
    for (int i = 0; i < k; ++i) q(i) = u(rng);
    const NormalContactSolution s = solve_normal_contact(M, q, 1e-13, 1000);
    ASSERT_TRUE(s.converged) << trial;
    const Eigen::VectorXd expected = by_enumeration(M, q);
    ASSERT_GE(expected.minCoeff(), 0.0) << trial;  // a strictly convex problem has one solution
    EXPECT_LT((s.force - expected).norm(), 1e-9 * (1.0 + expected.norm())) << trial;
    expect_complementary(M, q, s.force, 1e-10);
  }
}

TEST(NormalContactLcp, ClosePointsOfANearlySingularCompliance) {
  // Four contact points around one node under the tool: each moves with that node, so their
  // compliance is nearly the all-ones matrix (thesis eq. 5.11 with the shape functions); all
  // four are predicted into the tool.
  const int k = 4;
  const Eigen::MatrixXd M = Eigen::MatrixXd::Constant(k, k, 1e-3) + 1e-9 * Eigen::MatrixXd::Identity(k, k);
  const Eigen::VectorXd q = (Eigen::VectorXd(k) << -2e-4, -2.1e-4, -1.9e-4, -2.05e-4).finished();
  const NormalContactSolution s = solve_normal_contact(M, q, 1e-16, 1000);
  ASSERT_TRUE(s.converged);
  expect_complementary(M, q, s.force, 1e-12);
  // The deepest point alone carries the force that closes its gap; the others are then open.
  EXPECT_NEAR(s.force.sum(), 2.1e-4 / (1e-3 + 1e-9), 1e-9);
}

TEST(NormalContactLcp, PointsOnSupportedNodesGetNoForce) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2, 2);
  M(1, 1) = 2.0;
  const Eigen::VectorXd q = (Eigen::VectorXd(2) << -1.0, -1.0).finished();
  const NormalContactSolution s = solve_normal_contact(M, q, 1e-14, 100);
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.force(0), 0.0);
  EXPECT_DOUBLE_EQ(s.force(1), 0.5);
}

}  // namespace
}  // namespace spifit::contact
