// The two-domain CHOLMOD (split_cholmod.hpp) against exact solutions and the one-piece
// factorisation: a grid operator with three unknowns per node, periodic in one direction like
// a pie with cyclic ties, large enough (>= kSplitCholmodMinUnknowns) to be split.
#include "forward/solver/linear_solver.hpp"
#include "forward/solver/split_cholmod.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <omp.h>

using namespace spifit::solver;

namespace {

// nx x ny nodes, `per_node` unknowns each, periodic along x. Each bond between neighbouring
// nodes adds a coupled 2 x per_node block [C -C; -C C] with C symmetric positive definite (a
// spring per unknown plus a weak coupling of the unknowns); a diagonal shift makes it definite.
struct Grid {
  int nx, ny, per_node;
  std::vector<std::vector<int>> dofs;  // one "element" per bond
  Grid(int nx_, int ny_, int per_node_) : nx(nx_), ny(ny_), per_node(per_node_) {
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        bond(node(i, j), node((i + 1) % nx, j));
        if (j + 1 < ny) bond(node(i, j), node(i, j + 1));
      }
  }
  int node(int i, int j) const { return j * nx + i; }
  int unknowns() const { return nx * ny * per_node; }
  void bond(int a, int b) {
    std::vector<int> d;
    for (int n : {a, b})
      for (int k = 0; k < per_node; ++k) d.push_back(n * per_node + k);
    dofs.push_back(d);
  }
  SparseMatrix matrix(const SparsePattern& p, double shift) const {
    const AssemblyMap map = build_assembly_map(p, dofs);
    SparseMatrix K(p);
    Eigen::MatrixXd c = Eigen::MatrixXd::Constant(per_node, per_node, 0.2) + 0.8 * Eigen::MatrixXd::Identity(per_node, per_node);
    Eigen::MatrixXd ke(2 * per_node, 2 * per_node);
    ke << c, -c, -c, c;
    for (std::size_t e = 0; e < dofs.size(); ++e) K.add_element(map.positions[e], (1.0 + 0.1 * static_cast<double>(e % 7)) * ke);
    for (int r = 0; r < unknowns(); ++r) K.add(r, r, shift);
    return K;
  }
};

Eigen::VectorXd pattern_vector(int n) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = std::sin(0.37 * i) + 0.1 * (i % 11);
  return x;
}

}  // namespace

TEST(SplitCholmod, SolvesAPeriodicGridAndMatchesTheOnePieceFactor) {
  const Grid g(48, 30, 3);  // 4 320 unknowns
  ASSERT_GE(g.unknowns(), kSplitCholmodMinUnknowns);
  const SparsePattern p = build_pattern(g.unknowns(), g.dofs);
  const SparseMatrix K = g.matrix(p, 1e-3);
  const Eigen::VectorXd x_true = pattern_vector(g.unknowns());
  const Eigen::VectorXd b = K.multiply(x_true);
  auto split = make_split_cholmod();
  ASSERT_TRUE(split->factorize(K)) << split->error();
  EXPECT_NE(split->layout().find("split"), std::string::npos) << split->layout();
  Eigen::VectorXd x;
  ASSERT_TRUE(split->solve(b, &x)) << split->error();
  // The shift 1e-3 against bond stiffnesses ~1 makes K ill-conditioned (about 1e5): 1e-8.
  EXPECT_LT((x - x_true).norm() / x_true.norm(), 1e-8);
  auto whole = make_one_piece_cholmod();
  ASSERT_TRUE(whole->factorize(K));
  Eigen::VectorXd y;
  ASSERT_TRUE(whole->solve(b, &y));
  EXPECT_LT((x - y).norm() / y.norm(), 1e-9);
  EXPECT_LT((K.multiply(x) - b).norm() / b.norm(), 1e-12);
  // New values, same pattern: no new analysis.
  SparseMatrix K2 = g.matrix(p, 0.5);
  ASSERT_TRUE(split->factorize(K2));
  ASSERT_TRUE(split->solve(K2.multiply(x_true), &x));
  EXPECT_LT((x - x_true).norm() / x_true.norm(), 1e-12);
  EXPECT_EQ(split->symbolic_analyses(), 1);
  EXPECT_EQ(split->numeric_factorisations(), 2);
}

TEST(SplitCholmod, SameBitsWithOneAndTwoThreads) {
  const Grid g(48, 30, 3);
  const SparsePattern p = build_pattern(g.unknowns(), g.dofs);
  const SparseMatrix K = g.matrix(p, 0.01);
  const Eigen::VectorXd b = pattern_vector(g.unknowns());
  std::array<Eigen::VectorXd, 2> x;
  const int saved = omp_get_max_threads();
  for (int t : {1, 2}) {
    omp_set_num_threads(t);
    auto s = make_split_cholmod();
    ASSERT_TRUE(s->factorize(K)) << s->error();
    ASSERT_TRUE(s->solve(b, &x[static_cast<std::size_t>(t - 1)]));
  }
  omp_set_num_threads(saved);
  for (int i = 0; i < g.unknowns(); ++i) ASSERT_EQ(x[0](i), x[1](i)) << "unknown " << i;
}

TEST(SplitCholmod, ReportsAnIndefiniteMatrix) {
  const Grid g(48, 30, 3);
  const SparsePattern p = build_pattern(g.unknowns(), g.dofs);
  SparseMatrix K = g.matrix(p, 1e-3);
  K.add(100, 100, -50.0);  // one negative pivot in a domain
  auto s = make_split_cholmod();
  EXPECT_FALSE(s->factorize(K));
  EXPECT_NE(s->error().find("not positive definite"), std::string::npos) << s->error();
  Eigen::VectorXd x;
  EXPECT_FALSE(s->solve(Eigen::VectorXd::Ones(g.unknowns()), &x));
}

TEST(SplitCholmod, SmallSystemsStayInOnePiece) {
  const Grid g(10, 10, 3);  // 300 unknowns
  const SparsePattern p = build_pattern(g.unknowns(), g.dofs);
  const SparseMatrix K = g.matrix(p, 0.1);
  const Eigen::VectorXd x_true = pattern_vector(g.unknowns());
  auto s = make_split_cholmod();
  ASSERT_TRUE(s->factorize(K));
  EXPECT_EQ(s->layout(), "one piece");
  Eigen::VectorXd x;
  ASSERT_TRUE(s->solve(K.multiply(x_true), &x));
  EXPECT_LT((x - x_true).norm() / x_true.norm(), 1e-12);
}
