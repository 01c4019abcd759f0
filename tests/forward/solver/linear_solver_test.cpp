// Sparse pattern, assembly and the SuiteSparse solvers on problems with known solutions.
#include "forward/solver/linear_solver.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

using namespace spifit::solver;

namespace {

// 1D bar of n two-node elements (stiffness k = 1/h), fixed at x = 0 by a penalty-free
// elimination: dofs 1..n, load f per unit length. Exact nodal values u(x) = f x (2 - x) / 2
// (unit length, unit EA), which linear elements reproduce exactly at the nodes.
struct Bar {
  int n;
  std::vector<std::vector<int>> dofs;
  Bar(int elements) : n(elements) {
    for (int e = 0; e < n; ++e) {
      if (e == 0) dofs.push_back({0});
      else dofs.push_back({e - 1, e});
    }
  }
};

}  // namespace

TEST(SparsePattern, BuildAndFind) {
  const SparsePattern p = build_pattern(4, {{0, 1}, {1, 2}, {2, 3}});
  EXPECT_EQ(p.nonzeros(), 10);  // tridiagonal 4 x 4
  EXPECT_GE(p.find(1, 2), 0);
  EXPECT_EQ(p.find(0, 3), -1);
  // The diagonal's positions (stabilised increments add to it, NewtonOptions::stabilisation).
  ASSERT_EQ(p.diagonal.size(), 4u);
  for (int r = 0; r < 4; ++r) EXPECT_EQ(p.diagonal[static_cast<std::size_t>(r)], p.find(r, r));
  SparseMatrix a(p);
  a.add(1, 1, 2.0);
  a.add(1, 2, -1.0);
  a.add(2, 1, -1.0);
  a.add_to_diagonal(Eigen::Vector4d(0.5, 0.25, 0.125, 1.0));
  EXPECT_EQ(a.diagonal(), Eigen::Vector4d(0.5, 2.25, 0.125, 1.0));
  EXPECT_EQ(a.multiply(Eigen::Vector4d(0.0, 0.0, 1.0, 0.0)), Eigen::Vector4d(0.0, -1.0, 0.125, 0.0));  // off-diagonal untouched
  EXPECT_THROW(a.add_to_diagonal(Eigen::Vector2d(1.0, 1.0)), std::invalid_argument);
}

// The symmetric part of a non-symmetric tangent (NewtonOptions::symmetric_tangent): (A + A^T) / 2
// entry by entry, the source left as it was, and patterns that differ refused.
TEST(SparseMatrix, SymmetricPartAveragesMirroredEntries) {
  const SparsePattern p = build_pattern(3, {{0, 1}, {1, 2}});
  SparseMatrix a(p);
  a.add(0, 0, 4.0);
  a.add(0, 1, 1.0);
  a.add(1, 0, 3.0);
  a.add(1, 2, -2.0);
  a.add(2, 2, 5.0);
  SparseMatrix s(p);
  s.assign_symmetric_part(a);
  EXPECT_TRUE(s.is_symmetric(0.0));
  EXPECT_FALSE(a.is_symmetric(1e-10));
  EXPECT_EQ(s.multiply(Eigen::Vector3d(1.0, 0.0, 0.0)), Eigen::Vector3d(4.0, 2.0, 0.0));
  EXPECT_EQ(s.multiply(Eigen::Vector3d(0.0, 0.0, 1.0)), Eigen::Vector3d(0.0, -1.0, 5.0));
  EXPECT_EQ(a.multiply(Eigen::Vector3d(1.0, 0.0, 0.0)), Eigen::Vector3d(4.0, 3.0, 0.0));
  const SparsePattern other = build_pattern(3, {{0, 1}, {1, 2}});
  SparseMatrix b(other);
  EXPECT_THROW(b.assign_symmetric_part(a), std::invalid_argument);
}

TEST(LinearSolver, BarAgainstExactSolutionBothSolvers) {
  const int n = 200;
  const double h = 1.0 / n;
  Bar bar(n);
  const SparsePattern p = build_pattern(n, bar.dofs);
  const AssemblyMap map = build_assembly_map(p, bar.dofs);
  SparseMatrix K(p);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  for (int e = 0; e < n; ++e) {
    if (e == 0) {
      Eigen::MatrixXd k(1, 1);
      k << 1.0 / h;
      K.add_element(map.positions[e], k);
      f(0) += 0.5 * h;
    } else {
      Eigen::MatrixXd k(2, 2);
      k << 1.0 / h, -1.0 / h, -1.0 / h, 1.0 / h;
      K.add_element(map.positions[e], k);
      f(e - 1) += 0.5 * h;
      f(e) += 0.5 * h;
    }
  }
  EXPECT_TRUE(K.is_symmetric(1e-15));
  for (auto kind : {LinearSolverKind::umfpack, LinearSolverKind::cholmod}) {
    auto s = make_linear_solver(kind);
    ASSERT_TRUE(s->factorize(K)) << s->error();
    Eigen::VectorXd u;
    ASSERT_TRUE(s->solve(f, &u)) << s->error();
    for (int i = 0; i < n; ++i) {
      const double x = (i + 1) * h;
      EXPECT_NEAR(u(i), x * (2.0 - x) / 2.0, 1e-10);
    }
    // Refactorising after a value change reuses the symbolic analysis.
    for (double& v : K.values()) v *= 2.0;
    ASSERT_TRUE(s->factorize(K));
    ASSERT_TRUE(s->solve(f, &u));
    EXPECT_NEAR(u(n - 1), 0.25, 1e-10);
    EXPECT_EQ(s->symbolic_analyses(), 1);
    EXPECT_EQ(s->numeric_factorisations(), 2);
    for (double& v : K.values()) v *= 0.5;
  }
}

// A non-symmetric system (convection-diffusion stencil): UMFPACK against a dense solve.
TEST(LinearSolver, UmfpackNonSymmetric) {
  const int n = 60;
  std::vector<std::vector<int>> d;
  for (int i = 0; i + 1 < n; ++i) d.push_back({i, i + 1});
  const SparsePattern p = build_pattern(n, d);
  SparseMatrix A(p);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    A.add(i, i, 2.5);
    dense(i, i) = 2.5;
    if (i + 1 < n) { A.add(i, i + 1, -1.3); dense(i, i + 1) = -1.3; }
    if (i > 0) { A.add(i, i - 1, -0.7); dense(i, i - 1) = -0.7; }
  }
  EXPECT_FALSE(A.is_symmetric(1e-12));
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  auto s = make_linear_solver(LinearSolverKind::umfpack);
  ASSERT_TRUE(s->factorize(A));
  Eigen::VectorXd x;
  ASSERT_TRUE(s->solve(b, &x));
  const Eigen::VectorXd ref = dense.partialPivLu().solve(b);
  EXPECT_LT((x - ref).norm() / ref.norm(), 1e-13);
  EXPECT_LT((A.multiply(x) - b).norm(), 1e-12 * b.norm());
}

// Failures are statuses: a singular matrix (UMFPACK) and an indefinite one (CHOLMOD).
TEST(LinearSolver, FailuresAreReported) {
  const SparsePattern p = build_pattern(2, {{0, 1}});
  SparseMatrix A(p);
  A.add(0, 0, 1.0); A.add(0, 1, 1.0); A.add(1, 0, 1.0); A.add(1, 1, 1.0);  // singular
  auto u = make_linear_solver(LinearSolverKind::umfpack);
  EXPECT_FALSE(u->factorize(A));
  EXPECT_NE(u->error().find("singular"), std::string::npos);
  SparseMatrix B(p);
  B.add(0, 0, 1.0); B.add(0, 1, 2.0); B.add(1, 0, 2.0); B.add(1, 1, 1.0);  // indefinite
  auto c = make_linear_solver(LinearSolverKind::cholmod);
  EXPECT_FALSE(c->factorize(B));
  EXPECT_NE(c->error().find("positive definite"), std::string::npos);
}
