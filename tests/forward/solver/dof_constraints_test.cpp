// DofConstraints (supports, ties) and the cyclic ties of pies, solved by the Newton solver.
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/mesh/disc_mesh.hpp"
#include "forward/model/cyclic_symmetry.hpp"
#include "forward/model/hanging_nodes.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <utility>

namespace spifit::solver {
namespace {

using model::ShellModel;

material::MaterialParams<double> aluminium(bool plastic) {
  material::MaterialParams<double> p;
  p.E = 70000.0; p.nu = 0.3; p.hardening[material::SwiftHardening::K] = 100.0; p.hardening[material::SwiftHardening::eps0] = 0.001; p.hardening[material::SwiftHardening::n] = 0.2; p.plastic = plastic;
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
  expect_error([](DofConstraints& c) { c.tie(1, {{2, 1.0}}); c.tie(2, {{1, 1.0}}); }, "through a chain");
  expect_error([](DofConstraints& c) { c.tie(1, {{1, 1.0}}); }, "itself");
  expect_error([](DofConstraints& c) { c.prescribe(9); }, "out of range");
}

TEST(DofConstraints, ATiedMasterIsReplacedByItsOwnExpansion) {
  // u1 = 0.5 u0 + 0.5 u2, u2 = 2 u3 + 0.25 u4 (u4 prescribed to 4 per unit load), u5 = u1 - u0:
  // u1 = 0.5 u0 + u3 + 0.5, u5 = -0.5 u0 + u3 + 0.5 at load factor 1.
  DofConstraints c(6);
  c.tie(5, {{1, 1.0}, {0, -1.0}});
  c.tie(1, {{0, 0.5}, {2, 0.5}});
  c.tie(2, {{3, 2.0}, {4, 0.25}});
  c.prescribe(4, 4.0);
  c.finalize();
  ASSERT_EQ(c.num_reduced(), 2);
  const Eigen::VectorXd u = c.expand(Eigen::Vector2d(3.0, 7.0)) + c.prescribed_values(1.0);
  EXPECT_DOUBLE_EQ(u[0], 3.0);
  EXPECT_DOUBLE_EQ(u[3], 7.0);
  EXPECT_DOUBLE_EQ(u[4], 4.0);
  EXPECT_DOUBLE_EQ(u[2], 2.0 * 7.0 + 1.0);
  EXPECT_DOUBLE_EQ(u[1], 0.5 * 3.0 + 0.5 * 15.0);
  EXPECT_DOUBLE_EQ(u[5], u[1] - u[0]);
  // Terms on the same unknown are summed: u5 has one term on u0 (-0.5) and one on u3 (1).
  EXPECT_EQ(c.expansion(5).size(), 2u);
}

// A 90 deg pie whose second edge is tied to the rotated first edge (and whose hanging nodes, if
// any, follow their edges), rim pushed out by 1 %, z held: the exact solution is the homogeneous
// equibiaxial expansion u = 0.01 x everywhere. Returns the largest displacement error (mm) and
// the number of hanging nodes whose rotations were tied.
std::pair<double, int> pie_expansion_error(const mesh::Mesh& m) {
  ShellModel model(m, 0.5, aluminium(false), {});
  DofConstraints c(model.num_dofs());
  model::tie_cyclic_edges(model, "edge_theta0", "edge_theta1", 90.0, &c);
  model::tie_hanging_translations(model, &c);
  for (int n : m.node_sets.at("rim")) {
    const Eigen::Vector3d& p = m.nodes[static_cast<std::size_t>(n)];
    if (c.tied(ShellModel::dof(n, 0))) continue;  // the rim node on the second edge follows its partner
    c.prescribe(ShellModel::dof(n, 0), 0.01 * p.x());
    c.prescribe(ShellModel::dof(n, 1), 0.01 * p.y());
  }
  for (int n = 0; n < m.num_nodes(); ++n)
    if (!c.tied(ShellModel::dof(n, 2))) c.prescribe(ShellModel::dof(n, 2));
  const int tied_rotations = model::tie_hanging_rotations(model, &c);
  c.finalize();
  NewtonOptions no;
  no.linear = true;
  no.initial_increment = no.max_increment = 1.0;
  NewtonSolver s(model, c, no);
  EXPECT_TRUE(s.solve().converged);
  double err = 0.0;
  for (int n = 0; n < m.num_nodes(); ++n)
    err = std::max(err, (model.displacement(n) - 0.01 * Eigen::Vector3d(m.nodes[static_cast<std::size_t>(n)].x(), m.nodes[static_cast<std::size_t>(n)].y(), 0.0)).norm());
  return {err, tied_rotations};
}

// small_disc's 90 deg pie (4 elements per kite side) with its centre coarsened inside 7 mm: the
// hanging layer at 8 mm has 4 hanging nodes, two of them next to the pie's edges.
mesh::Mesh coarsened_small_pie() {
  mesh::DiscOptions o;
  o.radius = 10.0;
  o.angle_deg = 90.0;
  o.elements_per_45deg = 4;
  o.coarse_inside = 7.0;
  return mesh::disc_mesh(o);
}

TEST(CyclicSymmetry, PieReproducesTheHomogeneousExpansionOfADisc) {
  const double err = pie_expansion_error(small_disc(90.0)).first;
  std::printf("cyclic pie: largest displacement error %.3e mm (rim displacement 0.1 mm)\n", err);
  EXPECT_LT(err, 1e-12);
}

TEST(CyclicSymmetry, CoarsenedPieReproducesTheHomogeneousExpansion) {
  // The same expansion on a 90 deg pie whose centre is coarsened (disc_mesh's coarse_inside): the
  // hanging nodes next to the pie's edges have a master on an edge, and on edge_theta1 that master
  // is itself tied (a chain the constraints expand). A linear field is reproduced exactly.
  const mesh::Mesh m = coarsened_small_pie();
  ASSERT_EQ(m.constrained_nodes.size(), 4u);
  const auto [err, tied_rotations] = pie_expansion_error(m);
  EXPECT_EQ(tied_rotations, 4);  // no frames: every hanging node's x, y rotations
  std::printf("coarsened cyclic pie: largest displacement error %.3e mm (rim displacement 0.1 mm)\n", err);
  EXPECT_LT(err, 1e-12);
}

TEST(CyclicSymmetry, HangingNodesNextToAPiesEdgesKeepTheirRotationsInNodalFrames) {
  // With nodal rotation frames the edge nodes of a pie are not framed (their rotations are the
  // cyclic ties' masters or slaves in x, y, z): the two hanging nodes next to the edges keep their
  // own rotations, the two between framed masters are tied.
  const mesh::Mesh m = coarsened_small_pie();
  ShellModel model(m, 0.5, aluminium(false), {});
  DofConstraints c(model.num_dofs());
  model::tie_cyclic_edges(model, "edge_theta0", "edge_theta1", 90.0, &c);
  model::tie_hanging_translations(model, &c);
  model.use_nodal_rotation_frames(&c);
  EXPECT_EQ(model::tie_hanging_rotations(model, &c), 2);
  for (const mesh::ConstrainedNode& h : m.constrained_nodes) {
    EXPECT_TRUE(c.tied(ShellModel::dof(h.node, 0)));
    EXPECT_TRUE(model.has_rotation_frame(h.node));
  }
  c.finalize();
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
  if (angle_deg < 360.0) model::tie_cyclic_edges(model, "edge_theta0", "edge_theta1", angle_deg, &c);
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

}  // namespace
}  // namespace spifit::solver
