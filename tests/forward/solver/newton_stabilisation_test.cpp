// Stabilised increments (NewtonOptions::stabilisation) on a two-unknown snap-through.
#include "forward/io/binary_archive.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace spifit::solver {
namespace {

// Two unknowns with a stiff mode m = (u1 + u2) / 2 (stiffness A) and a soft mode
// s = (u1 - u2) / 2 whose force phi'(s) = s - 1.5 s^2 + 0.6 s^3 has a limit point (0.2010 at
// s = 0.4606) and a far branch beyond s = 1.206: energy A m^2 / 2 + phi(s), load lambda F on u1,
// so equilibrium is A m = lambda F, phi'(s) = lambda F. Past lambda F = 0.201 there is no
// equilibrium near the near branch: a snap-through, which a static Newton cannot cross at any
// increment size. The diagonal of the tangent, (A + phi'') / 4, stays large while the soft mode's
// stiffness phi'' / 2 goes through zero, as in a shell wall hinging under the tool.
class SnapThrough : public NonlinearProblem {
 public:
  SnapThrough(double stiff, double load) : a_(stiff), f_(load) {}
  int num_dofs() const override { return 2; }
  const std::vector<std::vector<int>>& element_dofs() const override { return dofs_; }
  static double force(double s) { return s - 1.5 * s * s + 0.6 * s * s * s; }
  static double stiffness(double s) { return 1.0 - 3.0 * s + 1.8 * s * s; }
  ElementEvaluation evaluate_element(int, Eigen::VectorXd* re, Eigen::MatrixXd* ke) override {
    const double m = 0.5 * (trial_(0) + trial_(1)), s = 0.5 * (trial_(0) - trial_(1));
    *re = Eigen::Vector2d(0.5 * (a_ * m + force(s)), 0.5 * (a_ * m - force(s)));
    if (ke) {
      const double k = stiffness(s);
      *ke = 0.25 * (Eigen::Matrix2d() << a_ + k, a_ - k, a_ - k, a_ + k).finished();
    }
    return {};
  }
  Eigen::VectorXd external_forces(double lambda) const override { return Eigen::Vector2d(lambda * f_, 0.0); }
  void set_trial(const Eigen::VectorXd& delta, double alpha) override { trial_ = iterate_ + alpha * delta; }
  void accept_trial() override { iterate_ = trial_; }
  void commit(double) override { committed_ = iterate_; }
  void revert() override { trial_ = iterate_ = committed_; }
  Eigen::VectorXd increment_from_committed() const override { return iterate_ - committed_; }
  Eigen::Vector2d u() const { return committed_; }
  void restore(const Eigen::Vector2d& u) { committed_ = iterate_ = trial_ = u; }

 private:
  double a_, f_;
  Eigen::Vector2d committed_ = Eigen::Vector2d::Zero(), iterate_ = committed_, trial_ = committed_;
  std::vector<std::vector<int>> dofs_{{0, 1}};
};

// Where a run would end at the minimum increment, stabilised increments carry it over the
// snap-through (docs/design/numerics-shell.md, "Stabilised increments"); the unstabilised increments after them end
// on the far branch's exact equilibrium, and a run resumed from a state inside the stabilised
// window ends bitwise where the uninterrupted one does.
TEST(NewtonSolver, StabilisedIncrementsCrossASnapThrough) {
  NewtonOptions o;
  o.initial_increment = o.max_increment = 0.1;
  o.min_increment = 1e-4;
  o.force_tolerance = o.displacement_tolerance = 1e-10;
  o.max_iterations = 20;
  o.stabilised_increments = 3;
  DofConstraints c(2);
  c.finalize();
  const double stiff = 1000.0, load = 0.3;
  {
    SnapThrough p(stiff, load);
    NewtonSolver plain(p, c, o);
    const NewtonSummary r = plain.solve(1.0);
    std::printf("unstabilised: %s (lambda %.4f)\n", r.message.c_str(), r.lambda);
    EXPECT_FALSE(r.converged);
    EXPECT_NE(r.message.find("minimum increment"), std::string::npos) << r.message;
    EXPECT_NEAR(r.lambda * load, 0.2010, 2e-3);  // stops at the limit point
    EXPECT_EQ(r.counters.stabilised_increments, 0);
  }
  o.stabilisation = 1e-3;  // c |diag K| = 0.25 against a soft stiffness down to -0.125
  SnapThrough p(stiff, load);
  NewtonSolver s(p, c, o);
  NewtonState inside;
  Eigen::Vector2d u_inside = Eigen::Vector2d::Zero();
  std::vector<IncrementReport> stabilised;
  const NewtonSummary r = s.solve(1.0, [&](const IncrementReport& ir) {
    if (ir.damping > 0.0) {
      stabilised.push_back(ir);
      if (stabilised.size() == 1) inside = s.state(), u_inside = p.u();
    }
    return true;
  });
  ASSERT_TRUE(r.converged) << r.message;
  const double m = 0.5 * (p.u()(0) + p.u()(1)), sf = 0.5 * (p.u()(0) - p.u()(1));
  std::printf("stabilised: %d increments, viscous work %.4g, largest viscous force %.3g; s = %.10f, m = %.3e; %d increments, %d iterations\n",
              r.counters.stabilised_increments, r.counters.viscous_work, r.counters.max_viscous_force, sf, m, r.counters.increments,
              r.counters.iterations);
  EXPECT_GT(sf, 1.206);  // on the far branch
  EXPECT_NEAR(SnapThrough::force(sf), load, 1e-9);
  EXPECT_NEAR(stiff * m, load, 1e-9);
  EXPECT_EQ(r.history.back().damping, 0.0);  // the last increment is a plain one
  ASSERT_EQ(static_cast<int>(stabilised.size()), r.counters.stabilised_increments);
  ASSERT_GE(r.counters.stabilised_increments, 1);
  double work = 0.0, largest = 0.0;
  for (const IncrementReport& ir : stabilised) {
    EXPECT_EQ(ir.damping, 1e-3);
    EXPECT_GT(ir.viscous_work, 0.0);
    work += ir.viscous_work;
    largest = std::max(largest, ir.viscous_force);
  }
  EXPECT_DOUBLE_EQ(r.counters.viscous_work, work);
  EXPECT_EQ(r.counters.max_viscous_force, largest);
  // Resumed inside the stabilised window (the state carries the damping and the increments it
  // still lasts, through a checkpoint archive), the run ends bitwise on the same state with the
  // same totals.
  ASSERT_GT(inside.damping, 0.0);
  ASSERT_GT(inside.stabilised_left, 0);
  io::BinaryWriter w("test", 1);
  save_newton_state(w, inside);
  io::BinaryReader rd(w.finish(), "test", 1);
  const NewtonState loaded = load_newton_state(rd);
  EXPECT_EQ(loaded.damping, inside.damping);
  EXPECT_EQ(loaded.stabilised_left, inside.stabilised_left);
  EXPECT_EQ(loaded.counters.stabilised_increments, inside.counters.stabilised_increments);
  EXPECT_EQ(loaded.counters.viscous_work, inside.counters.viscous_work);
  EXPECT_EQ(loaded.counters.max_viscous_force, inside.counters.max_viscous_force);
  SnapThrough q(stiff, load);
  q.restore(u_inside);
  NewtonSolver t(q, c, o);
  t.set_state(loaded);
  const NewtonSummary rr = t.resume(1.0, {});
  ASSERT_TRUE(rr.converged) << rr.message;
  EXPECT_EQ(q.u()(0), p.u()(0));
  EXPECT_EQ(q.u()(1), p.u()(1));
  EXPECT_EQ(rr.counters.iterations, r.counters.iterations);
  EXPECT_EQ(rr.counters.stabilised_increments, r.counters.stabilised_increments);
  EXPECT_EQ(rr.counters.viscous_work, r.counters.viscous_work);
}

}  // namespace
}  // namespace spifit::solver
