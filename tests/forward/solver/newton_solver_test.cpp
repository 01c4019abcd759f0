#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/benchmark/shell_benchmarks.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace spifit::solver {
namespace {

using model::ShellModel;

material::MaterialParams<double> aluminium(bool plastic) {
  material::MaterialParams<double> p;
  p.E = 70000.0; p.nu = 0.3; p.hardening[material::SwiftHardening::K] = 100.0; p.hardening[material::SwiftHardening::eps0] = 0.001; p.hardening[material::SwiftHardening::n] = 0.2; p.plastic = plastic;
  return p;
}

// A thick cantilever strip (10 x 1 x 1, 10 x 2 elements), clamped at one end, with a load of
// per_node along z on each of its three tip nodes.
struct Cantilever {
  Cantilever(bool plastic, double per_node)
      : mesh(mesh::strip(10.0, 1.0, 10, 2)), model(mesh, 1.0, aluminium(plastic), {}), constraints(model.num_dofs()) {
    for (int n : mesh.node_sets.at("clamped"))
      for (int k = 0; k < 6; ++k) constraints.prescribe(ShellModel::dof(n, k));
    for (int n : mesh.node_sets.at("tip")) model.add_nodal_load(ShellModel::dof(n, 2), per_node);
    constraints.finalize();
  }
  Cantilever(const Cantilever&) = delete;  // the model points at the mesh
  Cantilever& operator=(const Cantilever&) = delete;
  double tip() const { return model.displacement(mesh.node_sets.at("tip_centre")[0]).z(); }
  mesh::Mesh mesh;
  ShellModel model;
  DofConstraints constraints;
};

// The cantilever under a large tip load, solved in one increment (the solver may cut it back);
// returns the Newton corrections of the first converged increment.
std::vector<double> cantilever_corrections(bool plastic, double load) {
  Cantilever cant(plastic, load / 3.0);
  NewtonOptions o;
  o.initial_increment = o.max_increment = 1.0;
  o.max_iterations = 30;
  o.force_tolerance = 1e-9;
  NewtonSolver s(cant.model, cant.constraints, o);
  const NewtonSummary summary = s.solve();
  EXPECT_TRUE(summary.converged) << summary.message;
  const IncrementReport& r = summary.history.at(0);
  std::printf("%s, tip load %g: tip deflection %.4f\n  residuals:", plastic ? "plastic" : "elastic", load,
              cant.tip());
  for (double v : r.residual_norms) std::printf(" %.2e", v);
  std::printf("\n  corrections:");
  for (double v : r.correction_norms) std::printf(" %.2e", v);
  std::printf("\n");
  return r.correction_norms;
}

// Order of convergence from the last three corrections above the round-off floor.
double convergence_order(const std::vector<double>& d) {
  std::vector<double> e;
  for (double v : d)
    if (v > 1e-11 * d.front()) e.push_back(v);
  if (e.size() < 3) return 0.0;
  const std::size_t k = e.size() - 1;
  return std::log(e[k] / e[k - 1]) / std::log(e[k - 1] / e[k - 2]);
}

TEST(NewtonSolver, ConvergesQuadraticallyWithTheExactTangent) {
  const double p_elastic = convergence_order(cantilever_corrections(false, 300.0));
  const double p_plastic = convergence_order(cantilever_corrections(true, 3.0));
  std::printf("order of convergence: elastic %.2f, plastic %.2f\n", p_elastic, p_plastic);
  EXPECT_GT(p_elastic, 1.6);
  EXPECT_GT(p_plastic, 1.6);
}

// The cantilever's tip under a large load (the solver takes several increments), with the cone
// scenes' tolerances (1e-5 on force and displacement), with or without the estimated next
// correction.
struct CantileverRun {
  int iterations = 0, estimated = 0;
  double tip = 0.0;
};

CantileverRun cantilever_tip(bool estimate) {
  Cantilever cant(false, 40.0);
  NewtonOptions o;
  o.initial_increment = o.max_increment = 1.0;
  o.force_tolerance = o.displacement_tolerance = 1e-5;
  o.estimate_next_correction = estimate;
  NewtonSolver s(cant.model, cant.constraints, o);
  const NewtonSummary summary = s.solve();
  EXPECT_TRUE(summary.converged) << summary.message;
  CantileverRun run;
  run.iterations = summary.counters.iterations;
  std::printf("estimate %d:", estimate);
  for (const IncrementReport& r : summary.history) {
    std::printf(" [%d its, last residual %.2e%s]", r.iterations, r.residual_norms.back(), r.estimated ? ", estimated" : "");
    if (r.estimated) {
      ++run.estimated;
      // Accepted on the force test with a last correction that failed the displacement test
      // (1e-5 x an increment of about 1 mm of tip travel and its rotations).
      EXPECT_LE(r.residual_norms.back(), 1e-5);
      EXPECT_GT(r.correction_norms.back(), 1e-5);
    }
  }
  run.tip = cant.tip();
  std::printf(", tip %.10f\n", run.tip);
  return run;
}

TEST(NewtonSolver, TheEstimatedNextCorrectionSavesTheConfirmingIteration) {
  const CantileverRun plain = cantilever_tip(false), estimated = cantilever_tip(true);
  EXPECT_EQ(plain.estimated, 0);
  EXPECT_GT(estimated.estimated, 0);
  // Without the estimate such an increment iterates once more only to confirm it.
  EXPECT_LE(estimated.iterations, plain.iterations - estimated.estimated);
  // The states accepted earlier lie within the displacement tolerance of the confirmed ones.
  EXPECT_NEAR(estimated.tip, plain.tip, 1e-5 * std::abs(plain.tip));
}

// The cantilever's tip load in one increment with a given divergence_after (the solver cuts it
// back as it needs); the tip deflection at the end.
struct DivergenceRun {
  NewtonSummary summary;
  double tip = 0.0;
};

DivergenceRun cantilever_in_one_increment(double load, int divergence_after) {
  Cantilever cant(false, load / 3.0);
  NewtonOptions o;
  o.initial_increment = o.max_increment = 1.0;
  o.max_iterations = 25;
  o.divergence_after = divergence_after;
  NewtonSolver s(cant.model, cant.constraints, o);
  DivergenceRun run{s.solve(), cant.tip()};
  const NewtonSummary& m = run.summary;
  std::printf("divergence_after %d, load %g: %d increments, %d iterations, %d cut-backs, tip %.9f; first converged increment:",
              divergence_after, load, m.counters.increments, m.counters.iterations, m.counters.cutbacks, run.tip);
  if (!m.history.empty())
    for (double v : m.history.front().residual_norms) std::printf(" %.2e", v);
  std::printf("\n");
  return run;
}

// An increment whose residual is still above its starting value after 3 iterations often
// converges a few iterations later (large rotations here; the contact settling in the fine
// cone70 scene, which therefore waits 10 iterations): cutting it back at once costs more
// increments.
TEST(NewtonSolver, WaitingLongerBeforeTheDivergenceCutBackSavesIncrements) {
  const DivergenceRun three = cantilever_in_one_increment(3000.0, 3), ten = cantilever_in_one_increment(3000.0, 10);
  ASSERT_TRUE(three.summary.converged) << three.summary.message;
  ASSERT_TRUE(ten.summary.converged) << ten.summary.message;
  // Increments accepted with 10 that were above their starting residual at iteration 3 (the
  // rule with 3 cuts such an increment back); none with 3.
  auto late = [](const NewtonSummary& m) {
    int n = 0;
    for (const IncrementReport& r : m.history) n += r.residual_norms.size() > 4 && r.residual_norms[3] > r.residual_norms[0];
    return n;
  };
  EXPECT_EQ(late(three.summary), 0);
  EXPECT_GT(late(ten.summary), 0);
  EXPECT_LT(ten.summary.counters.cutbacks, three.summary.counters.cutbacks);
  EXPECT_LT(ten.summary.counters.increments, three.summary.counters.increments);
  EXPECT_LT(ten.summary.counters.iterations, three.summary.counters.iterations);
  // The same end state up to the increments' own effect: the section's thickness, updated at
  // every commit, makes an elastic shell's end state depend on its increments (7e-4 here).
  EXPECT_NEAR(ten.tip, three.tip, 2e-3 * std::abs(three.tip));
}

TEST(NewtonSolver, ResultsDoNotDependOnTheThreadCount) {
  std::vector<Eigen::Vector3d> first;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    scene::ShellBenchmark b = scene::make_shell_benchmark({"scordelis_lo", 8, 5});
    NewtonSolver s(*b.model, *b.constraints, b.solver);
    ASSERT_TRUE(s.solve().converged);
    std::vector<Eigen::Vector3d> u;
    for (int n = 0; n < b.model->num_nodes(); ++n) u.push_back(b.model->displacement(n));
    if (first.empty()) first = u;
    else
      for (std::size_t i = 0; i < u.size(); ++i) EXPECT_EQ(u[i], first[i]) << "node " << i;  // bitwise
  }
}

TEST(NewtonSolver, StopsAtTheMinimumIncrementAndSaysWhereAndWhy) {
  scene::ShellBenchmark b = scene::make_shell_benchmark({"limit_moment", 4, 5});
  b.solver.max_iterations = 1;  // cannot converge
  b.solver.min_increment = 1e-3;
  b.solver.initial_increment = 0.02;
  int increments = 0;
  NewtonSolver s(*b.model, *b.constraints, b.solver);
  const NewtonSummary r = s.solve(1.0, [&](const IncrementReport&) { return ++increments, true; });
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("minimum increment"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("no convergence in 1 iterations"), std::string::npos) << r.message;
  std::printf("%s\n", r.message.c_str());
  // Where: the node and component of the largest Newton correction (ShellModel::describe_dof).
  EXPECT_NE(r.message.find("largest correction"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find(" at node "), std::string::npos) << r.message;
  EXPECT_GT(r.counters.cutbacks, 0);
}

// One unknown u with internal force k u + eps sign(u - u_step): a step of height 2 eps in the
// force, like a few layer points switching between elastic and plastic. For an external force
// inside the step's range no equilibrium exists and Newton cycles across the step with a
// residual of 2 eps; for eps small against the load that residual meets the force tolerance.
class SteppedSpring : public NonlinearProblem {
 public:
  SteppedSpring(double k, double eps, double u_step) : k_(k), eps_(eps), u_step_(u_step) {}
  int num_dofs() const override { return 1; }
  const std::vector<std::vector<int>>& element_dofs() const override { return dofs_; }
  ElementEvaluation evaluate_element(int, Eigen::VectorXd* re, Eigen::MatrixXd* ke) override {
    *re = Eigen::VectorXd::Constant(1, k_ * trial_ + (trial_ > u_step_ ? eps_ : -eps_));
    if (ke) *ke = Eigen::MatrixXd::Constant(1, 1, k_);
    return {};
  }
  Eigen::VectorXd external_forces(double lambda) const override { return Eigen::VectorXd::Constant(1, lambda); }
  void set_trial(const Eigen::VectorXd& delta, double alpha) override { trial_ = iterate_ + alpha * delta(0); }
  void accept_trial() override { iterate_ = trial_; }
  void commit(double) override { committed_ = iterate_; }
  void revert() override { trial_ = iterate_ = committed_; }
  Eigen::VectorXd increment_from_committed() const override { return Eigen::VectorXd::Constant(1, iterate_ - committed_); }
  double u() const { return committed_; }

 private:
  double k_, eps_, u_step_;
  double committed_ = 0.0, iterate_ = 0.0, trial_ = 0.0;
  std::vector<std::vector<int>> dofs_{{0}};
};

// A run can end on such a cycle (docs/design/numerics-shell.md, "Global solution", Convergence): at the
// minimum increment the force test alone must decide, else the run ends on an iterate that
// meets the force tolerance.
TEST(NewtonSolver, AtTheMinimumIncrementTheForceTestAloneDecides) {
  auto run = [](double eps, bool force_only) {
    SteppedSpring spring(1.0, eps, 0.5);
    DofConstraints c(1);
    c.finalize();
    NewtonOptions o;
    o.initial_increment = o.min_increment = o.max_increment = 0.1;  // every increment is the smallest
    o.force_tolerance = 1e-8;
    o.displacement_tolerance = 1e-12;  // cannot be met while the iterate cycles
    o.max_iterations = 10;
    o.force_only_at_minimum = force_only;
    NewtonSolver s(spring, c, o);
    const NewtonSummary r = s.solve(0.5);  // the last load, 0.5, lies on the step
    std::printf("eps %g, force_only_at_minimum %d: %s, u = %.12f\n", eps, force_only, r.message.c_str(), spring.u());
    return std::make_pair(r, spring.u());
  };
  // Cycle residual 2e-9 against the load 0.5: 4e-9 <= 1e-8.
  const auto [with_rule, u] = run(1e-9, true);
  ASSERT_TRUE(with_rule.converged) << with_rule.message;
  EXPECT_TRUE(with_rule.history.back().force_only);
  EXPECT_FALSE(with_rule.history.front().force_only);  // the increments off the step converge fully
  EXPECT_NEAR(u, 0.5, 2e-9);
  const auto [without_rule, u0] = run(1e-9, false);
  EXPECT_FALSE(without_rule.converged);
  EXPECT_NE(without_rule.message.find("no convergence in 10 iterations"), std::string::npos) << without_rule.message;
  (void)u0;
  // A cycle whose residual misses the force tolerance still fails, rule or not.
  const auto [too_large, u1] = run(1e-7, true);
  EXPECT_FALSE(too_large.converged);
  EXPECT_NE(too_large.message.find("minimum increment"), std::string::npos) << too_large.message;
  (void)u1;
}

TEST(NewtonSolver, EnergyLineSearchIsUsedAndReachesTheSameSolution) {
  double z[2];
  int searches[2];
  for (int ls = 0; ls < 2; ++ls) {
    scene::ShellBenchmark b = scene::make_shell_benchmark({"rollup", 16, 5});
    b.solver.line_search = ls == 1;
    NewtonSolver s(*b.model, *b.constraints, b.solver);
    const NewtonSummary r = s.solve();
    ASSERT_TRUE(r.converged) << r.message;
    z[ls] = b.value(*b.model);
    searches[ls] = 0;
    for (const auto& h : r.history) searches[ls] += h.line_searches;
  }
  EXPECT_EQ(searches[0], 0);
  EXPECT_GT(searches[1], 0);
  // The runs take different increments; the thickness (bending lever arm) is updated per
  // increment, so they agree to the order of the membrane strain, not to the Newton tolerance.
  EXPECT_NEAR(z[1], z[0], 1e-4 * std::abs(z[0]));
}

TEST(NewtonSolver, IncrementsEndAtEveryBreakpointAndKeepTheirSize) {
  // The elastic cantilever strip under a moderate tip load.
  Cantilever cant(false, 10.0);
  NewtonOptions o;
  o.initial_increment = o.max_increment = 0.25;
  // 0.5499: the increment from 0.3 would end 1e-4 short of it (< 1e-3 x 0.25) and reaches it instead.
  o.breakpoints = {0.1, 0.3, 0.5499, 0.7};
  NewtonSolver s(cant.model, cant.constraints, o);
  std::vector<double> ends;
  const NewtonSummary r = s.solve(1.0, [&](const IncrementReport& ir) { return ends.push_back(ir.lambda), true; });
  ASSERT_TRUE(r.converged) << r.message;
  ASSERT_EQ(r.counters.cutbacks, 0);  // the sequence below assumes no cut-back
  const std::vector<double> expected = {0.1, 0.3, 0.5499, 0.7, 0.95, 1.0};
  ASSERT_EQ(ends.size(), expected.size());
  for (std::size_t i = 0; i < ends.size(); ++i) EXPECT_NEAR(ends[i], expected[i], 1e-12) << "increment " << i + 1;
  NewtonOptions bad;
  bad.breakpoints = {0.5, 0.2};
  EXPECT_NE(bad.validate().find("breakpoints"), std::string::npos);
}

// The committed increments of a run: their end load factors and iterations, the cut-backs in
// all, and every node's displacement at the end.
struct SteppedRun {
  std::vector<double> ends;
  std::vector<int> iterations;
  int cutbacks = 0;
  std::vector<Eigen::Vector3d> u;
};

// The cantilever under a large tip load from 0 to 1 with stops at 0.3 and 0.55: one solve per
// segment, or one solve with the stops as restarts, or as breakpoints.
enum class Stops { solves, restarts, breakpoints };
SteppedRun cantilever_with_stops(Stops how) {
  Cantilever cant(false, 1000.0);
  NewtonOptions o;
  o.initial_increment = 0.2;
  o.max_increment = 0.5;
  o.max_iterations = 25;
  const std::vector<double> stops = {0.3, 0.55};
  if (how == Stops::restarts) o.restarts = stops;
  if (how == Stops::breakpoints) o.breakpoints = stops;
  NewtonSolver s(cant.model, cant.constraints, o);
  SteppedRun run;
  auto record = [&](const IncrementReport& ir) {
    run.ends.push_back(ir.lambda);
    run.iterations.push_back(ir.iterations);
    return true;
  };
  double lambda = 0.0;
  for (double end : how == Stops::solves ? std::vector<double>{0.3, 0.55, 1.0} : std::vector<double>{1.0}) {
    const NewtonSummary r = s.solve(lambda, end, record);
    EXPECT_TRUE(r.converged) << r.message;
    run.cutbacks += r.counters.cutbacks;
    lambda = end;
  }
  for (int n = 0; n < cant.model.num_nodes(); ++n) run.u.push_back(cant.model.displacement(n));
  std::printf("stops as %s: %zu increments, %d cut-backs, tip %.12f; ends:", how == Stops::solves ? "solves" : how == Stops::restarts ? "restarts" : "breakpoints",
              run.ends.size(), run.cutbacks, cant.tip());
  for (std::size_t i = 0; i < run.ends.size(); ++i) std::printf(" %.6g (%d)", run.ends[i], run.iterations[i]);
  std::printf("\n");
  return run;
}

// A caller that stops at given load factors (the forming scenes stop at each named tool-path
// point) may run one solve with them as restarts instead of one solve per segment: the same
// increments, iterations and end state, bit for bit.
TEST(NewtonSolver, RestartsTakeTheIncrementsOfSegmentBySegmentSolves) {
  const SteppedRun solves = cantilever_with_stops(Stops::solves);
  const SteppedRun restarts = cantilever_with_stops(Stops::restarts);
  const SteppedRun breakpoints = cantilever_with_stops(Stops::breakpoints);
  EXPECT_EQ(restarts.ends, solves.ends);  // bitwise
  EXPECT_EQ(restarts.iterations, solves.iterations);
  EXPECT_EQ(restarts.cutbacks, solves.cutbacks);
  ASSERT_EQ(restarts.u.size(), solves.u.size());
  for (std::size_t n = 0; n < solves.u.size(); ++n) EXPECT_EQ(restarts.u[n], solves.u[n]) << "node " << n;  // bitwise
  // The run has cut-backs, and without the restart of the increment size at the stops (only
  // breakpoints there) it takes other increments: the comparison above depends on the restarts.
  EXPECT_GT(solves.cutbacks, 0);
  EXPECT_NE(breakpoints.ends, solves.ends);
  NewtonOptions bad;
  bad.restarts = {0.5, 0.5};
  EXPECT_NE(bad.validate().find("restarts"), std::string::npos);
}

TEST(NewtonOptions, ValidateNamesTheProblem) {
  NewtonOptions o;
  EXPECT_EQ(o.validate(), "");
  o.min_increment = 0.5;
  EXPECT_NE(o.validate().find("min_increment 0.5"), std::string::npos) << o.validate();
  // The solver refuses invalid options and unfinalised constraints instead of looping.
  scene::ShellBenchmark b = scene::make_shell_benchmark({"membrane_patch", 0, 0});
  EXPECT_THROW(NewtonSolver(*b.model, *b.constraints, o), std::invalid_argument);
  DofConstraints open(b.model->num_dofs());
  EXPECT_THROW(NewtonSolver(*b.model, open, NewtonOptions{}), std::logic_error);
  NewtonOptions st;
  st.stabilisation = -1.0;
  EXPECT_NE(st.validate().find("stabilisation must be >= 0"), std::string::npos) << st.validate();
  st.stabilisation = 1e-3;
  st.max_stabilisation = 1e-4;
  EXPECT_NE(st.validate().find("max_stabilisation"), std::string::npos) << st.validate();
}

}  // namespace
}  // namespace spifit::solver
