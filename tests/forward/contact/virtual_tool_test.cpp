// Virtual tools of a pie model (thesis Fig. 8.4; ToolContact::set_copies): the tangent with
// a copy in contact matches finite differences, and a 90 deg pie with cyclic ties indented by a
// tool exactly on its edge gives the tool force of the full disc.
#include "forward/element/director.hpp"
#include "forward/mesh/disc_mesh.hpp"
#include "forward/model/cyclic_symmetry.hpp"
#include "forward/model/tool_contact.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace spifit::model {
namespace {

material::MaterialParams<double> elastic() {
  material::MaterialParams<double> m;
  m.E = 70000.0;
  m.nu = 0.3;
  m.plastic = false;
  return m;
}

// Contact part of element e's residual and tangent: the model with the tool minus the same
// model without it (same configuration).
struct Twin {
  mesh::Mesh mesh;
  ShellModel with, without;
  Twin(const mesh::Mesh& m, double t) : mesh(m), with(mesh, t, elastic(), {}), without(mesh, t, elastic(), {}) {}
  void set_trial(const Eigen::VectorXd& delta) {
    with.set_trial(delta, 1.0);
    without.set_trial(delta, 1.0);
  }
  Eigen::VectorXd residual(int e) {
    Eigen::VectorXd a, b;
    with.evaluate_element(e, &a, nullptr);
    without.evaluate_element(e, &b, nullptr);
    return a - b;
  }
  Eigen::MatrixXd tangent(int e) {
    Eigen::VectorXd a, b;
    Eigen::MatrixXd ka, kb;
    with.evaluate_element(e, &a, &ka);
    without.evaluate_element(e, &b, &kb);
    return ka - kb;
  }
};

// Central differences (step 1e-7) of element e's contact residual about the accepted
// configuration, one column per element DOF.
Eigen::MatrixXd fd_tangent(Twin& twin, int e, Eigen::Index rows, Eigen::Index cols) {
  const auto& dofs = twin.with.element_dofs()[static_cast<std::size_t>(e)];
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(twin.with.num_dofs());
  Eigen::MatrixXd kfd(rows, cols);
  const double h = 1e-7;
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    Eigen::VectorXd d = zero;
    d(dofs[j]) = h;
    twin.set_trial(d);
    const Eigen::VectorXd rp = twin.residual(e);
    d(dofs[j]) = -h;
    twin.set_trial(d);
    const Eigen::VectorXd rm = twin.residual(e);
    kfd.col(static_cast<Eigen::Index>(j)) = (rp - rm) / (2.0 * h);
  }
  return kfd;
}

// The moment rows are compared in the plane normal to each node's director: the shell's
// tangent keeps the rotational geometric term projected there (director_to_dofs), the
// drilling moment having no stiffness to pair with. delta: the accepted nodal rotations.
Eigen::MatrixXd projected_moment_rows(const Twin& twin, int e, const Eigen::VectorXd& delta, Eigen::MatrixXd diff) {
  const auto& quad = twin.mesh.quads[static_cast<std::size_t>(e)];
  for (int I = 0; I < 4; ++I) {
    const int n = quad[static_cast<std::size_t>(I)];
    const Eigen::Vector3d d = element::rotate_by_vector(twin.with.director(n), delta.segment<3>(ShellModel::dof(n, 3)));
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - d * d.transpose();
    diff.middleRows(6 * I + 3, 3) = P * diff.middleRows(6 * I + 3, 3);
  }
  return diff;
}

// Largest relative error of the contact tangent against central differences over the elements
// the tools touch; *copy_elements counts the elements touched by a copy (not the real tool).
double worst_tangent_error(double mu, bool phong, int* copy_elements, int* touched) {
  mesh::DiscOptions o;
  o.radius = 10.0;
  o.angle_deg = 90.0;
  o.elements_per_45deg = 8;
  const double t = 0.5, R = 5.0;
  Twin twin(mesh::disc_mesh(o), t);
  contact::ContactOptions co;
  co.penalty = 1000.0;
  co.friction = mu;
  co.points = 3;
  co.surface = phong ? contact::ContactOptions::Surface::phong : contact::ContactOptions::Surface::flat;
  // The real tool straddles the edge theta = 0 (centre 0.3 mm outside the pie), the copy at
  // +90 deg straddles theta = 90 deg from inside; 0.05 mm deep, then dragged and pressed.
  const Eigen::Vector3d c0(7.0, -0.3, 0.5 * t + R - 0.05), drag(0.01, 0.004, -0.005);
  model::ToolContact& tool = model::attach_tool(twin.with, R, [=](double lambda) -> Eigen::Vector3d { return c0 + lambda * drag; }, co);
  tool.set_copies({90.0, -90.0});
  // Committed contact state (friction history) at lambda = 0, then a small deformation and
  // the drag over the increment.
  twin.with.begin_increment(0.0, 0.0);
  twin.with.internal_forces();
  twin.with.commit(0.0);
  EXPECT_GT(tool.summary_of_tool(0).active_points, 0);
  EXPECT_GT(tool.summary_of_tool(1).active_points, 0);  // the copy at +90 deg
  EXPECT_EQ(tool.summary_of_tool(2).active_points, 0);  // the copy at -90 deg misses the pie
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(twin.with.num_dofs());
  for (int n = 0; n < twin.mesh.num_nodes(); ++n) {
    const Eigen::Vector3d& p = twin.mesh.nodes[static_cast<std::size_t>(n)];
    delta(ShellModel::dof(n, 2)) = -1e-3 * std::sin(0.3 * p.x()) * std::cos(0.2 * p.y());
    delta(ShellModel::dof(n, 3)) = 2e-4 * std::cos(0.5 * p.x());
  }
  twin.set_trial(delta);
  twin.with.accept_trial();
  twin.without.accept_trial();
  twin.with.begin_increment(0.0, 1.0);

  ShellModel real_only(twin.mesh, t, elastic(), {});  // the same without copies: which elements does a copy touch?
  model::attach_tool(real_only, R, [=](double lambda) -> Eigen::Vector3d { return c0 + lambda * drag; }, co);
  real_only.set_trial(delta, 1.0);
  real_only.accept_trial();
  real_only.begin_increment(0.0, 1.0);

  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(twin.with.num_dofs());
  double worst = 0.0;
  *copy_elements = *touched = 0;
  for (int e = 0; e < twin.mesh.num_elements(); ++e) {
    twin.set_trial(zero);
    const Eigen::MatrixXd k = twin.tangent(e);
    if (k.norm() == 0.0) continue;
    ++*touched;
    Eigen::VectorXd r_real, r_all;
    real_only.evaluate_element(e, &r_real, nullptr);
    twin.with.evaluate_element(e, &r_all, nullptr);
    if ((r_real - r_all).norm() > 0.0) ++*copy_elements;
    const Eigen::MatrixXd diff = projected_moment_rows(twin, e, delta, k - fd_tangent(twin, e, k.rows(), k.cols()));
    worst = std::max(worst, diff.norm() / k.norm());
  }
  return worst;
}

TEST(VirtualTool, TangentMatchesFiniteDifferencesWithACopyInContact) {
  for (int variant = 0; variant < 6; ++variant) {
    const double mu = std::array<double, 3>{0.0, 0.3, 0.02}[static_cast<std::size_t>(variant % 3)];  // frictionless, stick, slip
    const bool phong = variant >= 3;
    int copy_elements = 0, touched = 0;
    const double err = worst_tangent_error(mu, phong, &copy_elements, &touched);
    std::printf("%s mu %.2f: %d elements in contact, %d of them with the copy at +90 deg, worst tangent error %.2e\n",
                phong ? "phong" : "flat", mu, touched, copy_elements, err);
    EXPECT_GT(copy_elements, 0);
    EXPECT_LT(err, 1e-6);
  }
}

// An elastic disc or pie (radius 40 mm, t = 1, clamped rim, 12 elements per 45 deg) indented
// 0.3 mm by a tool (R = 5) whose centre is above (38, 0), i.e. exactly on the pie edge
// theta = 0. The pie model is the sheet under four tools 90 deg apart; near the clamp their
// mutual influence is small (tool 2 mm from the clamp: 0.3 % on the force; at 3 mm from the
// clamp of a 20 mm disc it was 2.7 %, at 5 mm 9.5 %).
struct Indent {
  Eigen::Vector3d tool_force;       // ToolContact::force (real tool + copies rotated back)
  Eigen::Vector3d real_tool_force;  // the real tool's own contact only
  int iterations = 0;
};

constexpr double kDiscRadius = 40.0, kToolAt = 38.0;

Indent indent(double angle_deg, const std::vector<double>& copies) {
  mesh::DiscOptions o;
  o.radius = kDiscRadius;
  o.angle_deg = angle_deg;
  o.elements_per_45deg = 12;
  const mesh::Mesh m = mesh::disc_mesh(o);
  const double t = 1.0, R = 5.0, depth = 0.3;
  ShellModel model(m, t, elastic(), {});
  contact::ContactOptions co;
  co.points = 3;
  spifit::model::ToolContact& tool = spifit::model::attach_tool(model, R, [=](double lambda) { return Eigen::Vector3d(kToolAt, 0.0, 0.5 * t + R - depth * lambda); }, co);
  tool.set_copies(copies);
  solver::DofConstraints c(model.num_dofs());
  if (angle_deg < 360.0) tie_cyclic_edges(model, "edge_theta0", "edge_theta1", angle_deg, &c);
  for (int n : m.node_sets.at("rim"))
    for (int k = 0; k < 6; ++k)
      if (!c.tied(ShellModel::dof(n, k))) c.prescribe(ShellModel::dof(n, k));
  c.finalize();
  solver::NewtonOptions no;
  no.initial_increment = no.max_increment = 0.25;
  // Tight tolerances for the exact comparison; the pie without virtual tools (its contact
  // points at the edge switch on and off) stalls at a relative residual of 2e-5 with 1e-10 and
  // converges with 1e-8, plenty for a difference of tens of percent.
  no.force_tolerance = no.displacement_tolerance = copies.empty() && angle_deg < 360.0 ? 1e-8 : 1e-10;
  solver::NewtonSolver s(model, c, no);
  const auto r = s.solve();
  EXPECT_TRUE(r.converged) << r.message;
  return {tool.force(), -tool.summary_of_tool(0).force_on_sheet, r.counters.iterations};
}

TEST(VirtualTool, PieIndentedOnItsEdgeGivesTheToolForceOfTheFullDisc) {
  // The exact counterpart of the pie: the full disc under four tools 90 deg apart (the pie
  // model's cyclic structure); its real tool must feel the pie's force to the Newton tolerance.
  const Indent pie = indent(90.0, {90.0, -90.0});
  const Indent four = indent(360.0, {90.0, 180.0, 270.0});
  const Indent one = indent(360.0, {});
  const Indent no_copies = indent(90.0, {});
  auto print = [](const char* what, const Eigen::Vector3d& f, int it) {
    std::printf("%-38s F = (%.6f, %.6f, %.6f) N  (%d iterations)\n", what, f.x(), f.y(), f.z(), it);
  };
  print("90 deg pie + virtual tools", pie.tool_force, pie.iterations);
  print("  of which the real tool's own contact", pie.real_tool_force, pie.iterations);
  print("full disc, four tools (real one)", four.real_tool_force, four.iterations);
  print("full disc, one tool", one.tool_force, one.iterations);
  print("90 deg pie without virtual tools", no_copies.tool_force, no_copies.iterations);
  const double fz = one.tool_force.z();
  ASSERT_GT(fz, 0.0);
  const double exact = (pie.tool_force - four.real_tool_force).norm() / four.real_tool_force.norm();
  const double single = (pie.tool_force - one.tool_force).norm() / fz;
  const double without = (no_copies.tool_force - one.tool_force).norm() / fz;
  std::printf("relative difference to the full disc: four tools %.2e, one tool %.2e; pie without virtual tools vs one tool %.2e\n",
              exact, single, without);
  EXPECT_LT(exact, 1e-6);
  EXPECT_LT(single, 0.01);
  EXPECT_GT(without, 0.2);
  // Half of the footprint is on the pie, half is seen through the copy at +90 deg.
  EXPECT_NEAR(pie.real_tool_force.z() / pie.tool_force.z(), 0.5, 0.05);
}

}  // namespace
}  // namespace spifit::model
