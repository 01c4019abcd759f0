#include "forward/io/binary_archive.hpp"
#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/mesh/disc_mesh.hpp"
#include "forward/model/cyclic_symmetry.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/shell_benchmarks.hpp"
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
  p.E = 70000.0; p.nu = 0.3; p.K = 100.0; p.eps0 = 0.001; p.n = 0.2; p.plastic = plastic;
  return p;
}

// A disc or pie of radius 10 mm, 4 elements per 45 deg (disc_mesh's O-grid of sub-sectors of at
// most max_sector_deg).
mesh::Mesh small_disc(double angle_deg, double max_sector_deg = mesh::DiscOptions{}.max_sector_deg) {
  mesh::DiscOptions o;
  o.radius = 10.0;
  o.angle_deg = angle_deg;
  o.elements_per_45deg = 4;
  o.max_sector_deg = max_sector_deg;
  return mesh::disc_mesh(o);
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

TEST(DofConstraints, ExpandsAndReducesWithTies) {
  DofConstraints c(4);
  c.prescribe(0, 2.0);
  c.tie(3, {{1, 0.5}, {0, 1.0}});  // u3 = 0.5 u1 + u0 = 0.5 u1 + 2 lambda
  c.finalize();
  EXPECT_EQ(c.num_reduced(), 2);
  EXPECT_DOUBLE_EQ(c.amplitude(3), 2.0);
  const Eigen::VectorXd full = c.expand(Eigen::Vector2d(4.0, 6.0));
  EXPECT_DOUBLE_EQ(full(1), 4.0);
  EXPECT_DOUBLE_EQ(full(2), 6.0);
  EXPECT_DOUBLE_EQ(full(3), 2.0);
  const Eigen::VectorXd red = c.reduce(Eigen::Vector4d(1.0, 1.0, 1.0, 1.0));  // T^T f
  EXPECT_DOUBLE_EQ(red(0), 1.5);
  EXPECT_DOUBLE_EQ(red(1), 1.0);
}

TEST(DofConstraints, InconsistentConstraintsAreErrors) {
  auto expect_error = [](const std::function<void(DofConstraints&)>& f, const std::string& fragment) {
    DofConstraints c(6);
    try {
      f(c);
      c.finalize();
      ADD_FAILURE() << "no error for " << fragment;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("inconsistent constraint"), std::string::npos) << e.what();
    }
  };
  expect_error([](DofConstraints& c) { c.prescribe(1, 1.0); c.prescribe(1, 2.0); }, "prescribed to");
  expect_error([](DofConstraints& c) { c.prescribe(1); c.tie(1, {{2, 1.0}}); }, "prescribed and tied");
  expect_error([](DofConstraints& c) { c.tie(1, {{2, 1.0}}); c.tie(2, {{3, 1.0}}); }, "chains");
  expect_error([](DofConstraints& c) { c.tie(1, {{1, 1.0}}); }, "itself");
  expect_error([](DofConstraints& c) { c.prescribe(9); }, "out of range");
}

TEST(CyclicSymmetry, PieReproducesTheHomogeneousExpansionOfADisc) {
  // A 90 deg pie whose second edge is tied to the rotated first edge, rim pushed out by 1 %:
  // the exact solution is the homogeneous equibiaxial expansion u = 0.01 x everywhere.
  const mesh::Mesh m = small_disc(90.0);
  ShellModel model(m, 0.5, aluminium(false), {});
  DofConstraints c(model.num_dofs());
  model::tie_cyclic_edges(m, "edge_theta0", "edge_theta1", 90.0, &c);
  for (int n : m.node_sets.at("rim")) {
    const Eigen::Vector3d& p = m.nodes[static_cast<std::size_t>(n)];
    if (c.tied(ShellModel::dof(n, 0))) continue;  // the rim node on the second edge follows its partner
    c.prescribe(ShellModel::dof(n, 0), 0.01 * p.x());
    c.prescribe(ShellModel::dof(n, 1), 0.01 * p.y());
  }
  for (int n = 0; n < m.num_nodes(); ++n)
    if (!c.tied(ShellModel::dof(n, 2))) c.prescribe(ShellModel::dof(n, 2));
  c.finalize();
  NewtonOptions no;
  no.linear = true;
  no.initial_increment = no.max_increment = 1.0;
  NewtonSolver s(model, c, no);
  ASSERT_TRUE(s.solve().converged);
  double err = 0.0;
  for (int n = 0; n < m.num_nodes(); ++n)
    err = std::max(err, (model.displacement(n) - 0.01 * Eigen::Vector3d(m.nodes[static_cast<std::size_t>(n)].x(), m.nodes[static_cast<std::size_t>(n)].y(), 0.0)).norm());
  std::printf("cyclic pie: largest displacement error %.3e mm (rim displacement 0.1 mm)\n", err);
  EXPECT_LT(err, 1e-12);
}

// The disc (angle 360) or 90 deg pie of an orthotropic Hill sheet (card C.3's F, G, H, N) whose rim
// is pushed out radially by 2 % (plastic), kept flat; a pie carries the cyclic ties. Returns the
// displacement of every node, by node number.
std::vector<Eigen::Vector3d> expand_orthotropic(double angle_deg, model::ShellModelOptions::MaterialAxes axes, mesh::Mesh* out) {
  *out = small_disc(angle_deg, 45.0);  // 45 deg sub-sectors: the pie is an exact quarter of the disc
  const mesh::Mesh& m = *out;
  material::MaterialParams<double> p = aluminium(true);
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;
  model::ShellModelOptions mo;
  mo.material_axes = axes;
  ShellModel model(m, 0.5, p, mo);
  DofConstraints c(model.num_dofs());
  if (angle_deg < 360.0) model::tie_cyclic_edges(m, "edge_theta0", "edge_theta1", angle_deg, &c);
  for (int n : m.node_sets.at("rim")) {
    const Eigen::Vector3d& x = m.nodes[static_cast<std::size_t>(n)];
    if (c.tied(ShellModel::dof(n, 0))) continue;
    c.prescribe(ShellModel::dof(n, 0), 0.02 * x.x());
    c.prescribe(ShellModel::dof(n, 1), 0.02 * x.y());
  }
  for (int n = 0; n < m.num_nodes(); ++n)
    if (!c.tied(ShellModel::dof(n, 2)) && !c.prescribed(ShellModel::dof(n, 2))) c.prescribe(ShellModel::dof(n, 2));
  c.finalize();
  NewtonOptions no;
  no.initial_increment = no.max_increment = 0.25;
  NewtonSolver s(model, c, no);
  EXPECT_TRUE(s.solve().converged);
  std::vector<Eigen::Vector3d> u;
  for (int n = 0; n < m.num_nodes(); ++n) u.push_back(model.displacement(n));
  return u;
}

// Largest difference between the pie's displacements and the disc's at the same nodes, over the
// largest disc displacement.
double pie_against_disc(model::ShellModelOptions::MaterialAxes axes) {
  mesh::Mesh pie, disc;
  const auto up = expand_orthotropic(90.0, axes, &pie);
  const auto ud = expand_orthotropic(360.0, axes, &disc);
  double diff = 0.0, scale = 0.0;
  int matched = 0;
  for (int a = 0; a < pie.num_nodes(); ++a)
    for (int b = 0; b < disc.num_nodes(); ++b)
      if ((pie.nodes[static_cast<std::size_t>(a)] - disc.nodes[static_cast<std::size_t>(b)]).norm() < 1e-9) {
        diff = std::max(diff, (up[static_cast<std::size_t>(a)] - ud[static_cast<std::size_t>(b)]).norm());
        ++matched;
      }
  for (const auto& v : ud) scale = std::max(scale, v.norm());
  EXPECT_EQ(matched, pie.num_nodes());
  return diff / scale;
}

TEST(CyclicSymmetry, PolarMaterialAxesMakeAPieOfAnOrthotropicSheetEqualToItsDisc) {
  // The cyclic ties assume the same material in every pie. With the rolling direction x
  // everywhere (fixed axes) a disc of an orthotropic sheet does not expand axisymmetrically and
  // its pie cannot follow it; with the rolling direction radial in every element (polar axes)
  // the disc is the same in every quarter and the pie is exact.
  const double fixed = pie_against_disc(model::ShellModelOptions::MaterialAxes::fixed);
  const double polar = pie_against_disc(model::ShellModelOptions::MaterialAxes::polar);
  std::printf("orthotropic expansion, pie vs disc (relative): fixed axes %.3e, polar axes %.3e\n", fixed, polar);
  EXPECT_LT(polar, 1e-9);
  EXPECT_GT(fixed, 1e-3);
}

TEST(CyclicSymmetry, PolarMaterialAxesAreRadialAtTheElementCentroid) {
  const mesh::Mesh m = small_disc(90.0);
  model::ShellModelOptions mo;
  mo.material_axes = model::ShellModelOptions::MaterialAxes::polar;
  mo.shell.material_axis = Eigen::Vector3d(0.0, 1.0, 0.0);  // rolling direction circumferential
  const ShellModel polar(m, 0.5, aluminium(true), mo);
  const ShellModel fixed(m, 0.5, aluminium(true), {});
  for (int e = 0; e < m.num_elements(); ++e) {
    const auto& q = m.quads[static_cast<std::size_t>(e)];
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : q) c += 0.25 * m.nodes[static_cast<std::size_t>(n)];
    const double t = std::atan2(c.y(), c.x());
    EXPECT_NEAR((polar.material_axis(e) - Eigen::Vector3d(-std::sin(t), std::cos(t), 0.0)).norm(), 0.0, 1e-14) << "element " << e;
    EXPECT_EQ(fixed.material_axis(e), Eigen::Vector3d::UnitX());
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

// The fine cone70 run stopped in contour 88 on such a cycle (docs/numerics-shell.md): at the
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
// snap-through (the fine cone70 contour 88 and the vwall contour 149 end that way,
// docs/numerics-shell.md "Stabilised increments"); the unstabilised increments after them end
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
