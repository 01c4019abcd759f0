// GMRES with right preconditioning on small dense systems with known solutions.
#include "forward/solver/preconditioned_gmres.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace spifit::solver {
namespace {

// A non-symmetric system A = S + U (S symmetric positive definite, U a small skew-ish part, as a
// sliding friction tangent is to its symmetric part) and its solution.
struct System {
  Eigen::MatrixXd s, a;
  Eigen::VectorXd x, b;
};

System system(int n, double unsymmetric) {
  System out;
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) r(i, j) = std::sin(1.0 + i * 7 + j * 3);
  out.s = r * r.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i + 1 < n; ++i) u(i, i + 1) = unsymmetric * n;
  out.a = out.s + u;
  out.x = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  out.b = out.a * out.x;
  return out;
}

GmresResult solve(const Eigen::MatrixXd& a, const Eigen::MatrixXd& m, const Eigen::VectorXd& b, Eigen::VectorXd* x, double tol, int iterations) {
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(m);
  return preconditioned_gmres([&](const Eigen::VectorXd& v) { return Eigen::VectorXd(a * v); },
                              [&](const Eigen::VectorXd& v, Eigen::VectorXd* z) {
                                *z = lu.solve(v);
                                return true;
                              },
                              b, x, tol, iterations);
}

TEST(PreconditionedGmres, ExactPreconditionerSolvesInOneStep) {
  const System s = system(30, 0.1);
  Eigen::VectorXd x;
  const GmresResult r = solve(s.a, s.a, s.b, &x, 1e-12, 20);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_LT((x - s.x).norm(), 1e-12 * s.x.norm());
}

// The symmetric part as preconditioner of a mildly non-symmetric matrix: a few iterations, and
// the true residual meets the tolerance the Arnoldi relation reported.
TEST(PreconditionedGmres, SymmetricPartPreconditionsASlidingTangent) {
  const System s = system(60, 0.05);
  Eigen::VectorXd x;
  const GmresResult r = solve(s.a, s.s, s.b, &x, 1e-12, 20);
  ASSERT_TRUE(r.converged);
  EXPECT_GT(r.iterations, 2);
  EXPECT_LT(r.iterations, 15);
  EXPECT_LE((s.b - s.a * x).norm(), 2e-12 * s.b.norm());
  EXPECT_NEAR(r.relative_residual, (s.b - s.a * x).norm() / s.b.norm(), 1e-13);
  EXPECT_LT((x - s.x).norm(), 1e-10 * s.x.norm());
}

TEST(PreconditionedGmres, GivesUpAfterItsIterationsAndTakesAZeroRightHandSide) {
  const System s = system(60, 0.05);
  Eigen::VectorXd x;
  const GmresResult r = solve(s.a, Eigen::MatrixXd::Identity(60, 60), s.b, &x, 1e-14, 3);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_GT(r.relative_residual, 1e-14);
  EXPECT_LT((s.b - s.a * x).norm(), s.b.norm());  // the best of the three-dimensional Krylov space
  const GmresResult zero = solve(s.a, s.s, Eigen::VectorXd::Zero(60), &x, 1e-12, 5);
  EXPECT_TRUE(zero.converged);
  EXPECT_EQ(x, Eigen::VectorXd::Zero(60));
  // A failing preconditioner ends the iteration unconverged.
  const GmresResult failed = preconditioned_gmres([&](const Eigen::VectorXd& v) { return Eigen::VectorXd(s.a * v); },
                                                  [](const Eigen::VectorXd&, Eigen::VectorXd*) { return false; }, s.b, &x, 1e-12, 5);
  EXPECT_FALSE(failed.converged);
  EXPECT_EQ(failed.iterations, 0);
}

}  // namespace
}  // namespace spifit::solver
