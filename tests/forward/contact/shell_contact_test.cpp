#include "forward/contact/shell_contact.hpp"
#include "forward/element/quad_shape.hpp"
#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/tool_contact.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace spifit::contact {
namespace {

using element::Mat24;
using element::NodeVectors;
using element::Vec24;

// One element 2 x 2 mm, slightly warped, directors tilted; a 5 mm tool pressing on it.
struct OneElement {
  mesh::Mesh mesh = mesh::strip(2.0, 2.0, 1, 1);
  NodeVectors x, d;
  OneElement() {
    for (int i = 0; i < 4; ++i) {
      x[static_cast<std::size_t>(i)] = mesh.nodes[static_cast<std::size_t>(mesh.quads[0][static_cast<std::size_t>(i)])];
      d[static_cast<std::size_t>(i)] = Eigen::Vector3d(0.02 * i, -0.01 * i, 1.0).normalized();
    }
    x[2].z() += 0.01;
  }
};

double fd_error(ShellContact& c, const NodeVectors& x, const NodeVectors& d, const SphereTool& tool) {
  Vec24 r = Vec24::Zero();
  Mat24 k = Mat24::Zero();
  EXPECT_TRUE(c.element(0, x, d, x, d, 0.25, tool, &r, &k, nullptr));
  Mat24 kfd;
  const double h = 1e-7;
  for (int j = 0; j < 24; ++j) {
    Vec24 rr[2];
    for (int s = 0; s < 2; ++s) {
      NodeVectors xp = x, dp = d;
      const std::size_t node = static_cast<std::size_t>(j / 6);
      const int comp = j % 6;
      (comp < 3 ? xp[node](comp) : dp[node](comp - 3)) += s == 0 ? h : -h;
      rr[s].setZero();
      c.element(0, xp, dp, x, d, 0.25, tool, &rr[s], nullptr, nullptr);
    }
    kfd.col(j) = (rr[0] - rr[1]) / (2.0 * h);
  }
  return (k - kfd).norm() / k.norm();
}

TEST(ShellContact, TangentMatchesFiniteDifferencesFrictionlessStickAndSlip) {
  for (int variant = 0; variant < 6; ++variant) {
    const double mu = std::array<double, 3>{0.0, 0.3, 0.02}[static_cast<std::size_t>(variant % 3)];  // frictionless, sticking, sliding
    const bool phong = variant >= 3;
    OneElement s;
    ContactOptions o;
    o.surface = phong ? ContactOptions::Surface::phong : ContactOptions::Surface::flat;
    o.penalty = 1000.0;
    o.friction = mu;
    o.points = 3;
    ShellContact c(s.mesh, o);
    SphereTool tool;
    tool.radius = 5.0;
    tool.centre = tool.centre_committed = Eigen::Vector3d(1.0, 0.0, 0.25 + 5.0 - 0.15);
    Vec24 r = Vec24::Zero();
    ASSERT_TRUE(c.element(0, s.x, s.d, s.x, s.d, 0.25, tool, &r, nullptr, nullptr));
    c.commit();
    // Drag the tool 0.01 mm along x and 0.004 along y, press 0.005 deeper: stick or slip.
    tool.centre_committed = tool.centre;
    tool.centre += Eigen::Vector3d(0.01, 0.004, -0.005);
    ContactSummary sum;
    Vec24 r2 = Vec24::Zero();
    c.element(0, s.x, s.d, s.x, s.d, 0.25, tool, &r2, nullptr, &sum);
    const double err = fd_error(c, s.x, s.d, tool);
    std::printf("%s mu %.2f: %d active points, tangential/normal %.4f, tangent error %.2e\n", phong ? "phong" : "flat", mu, sum.active_points,
                std::hypot(sum.force_on_sheet.x(), sum.force_on_sheet.y()) / sum.force_on_sheet.z(), err);
    EXPECT_LT(err, 1e-6);
  }
}

// A spinning tool (rotation vector spin over the increment about +z) drags the sheet along its
// surface velocity spin x (x - centre): at a single contact point 1 mm beside the tool axis the
// friction traction on the sheet is mu p along spin x (x - c) (here -y), horizontal; the
// tangent with spin matches central differences, and without spin a static tool has no friction.
TEST(ShellContact, SpinningToolDragsTheSheetAlongItsSurfaceVelocity) {
  mesh::Mesh m = mesh::strip(2.0, 2.0, 1, 1);
  NodeVectors x, d;
  for (std::size_t i = 0; i < 4; ++i) {
    x[i] = m.nodes[static_cast<std::size_t>(m.quads[0][i])];
    d[i] = Eigen::Vector3d::UnitZ();
  }
  ContactOptions o;
  o.friction = 0.2;
  o.points = 1;  // one point at the element centre (1, 0, 0.25)
  const double R = 5.0;
  SphereTool tool;
  tool.radius = R;
  tool.centre = tool.centre_committed = Eigen::Vector3d(2.0, 0.0, 0.25 + std::sqrt(R * R - 1.0) - 0.05);
  for (double spin : {0.0, 0.5, -0.5}) {
    ShellContact c(m, o);
    tool.spin = Eigen::Vector3d(0.0, 0.0, spin);
    Vec24 r = Vec24::Zero();
    ContactSummary sum;
    ASSERT_TRUE(c.element(0, x, d, x, d, 0.25, tool, &r, nullptr, &sum));
    ASSERT_EQ(sum.active_points, 1);
    const Eigen::Vector3d f = sum.force_on_sheet;
    const Eigen::Vector3d n = (Eigen::Vector3d(1.0, 0.0, 0.25) - tool.centre).normalized();
    const Eigen::Vector3d ft = f - f.dot(n) * n;
    std::printf("spin %+.1f rad: force on sheet (%.4f, %.4f, %.4f) N, |Ft|/|Fn| %.6f\n", spin, f.x(), f.y(), f.z(),
                ft.norm() / std::abs(f.dot(n)));
    if (spin == 0.0) {
      EXPECT_LT(ft.norm(), 1e-12 * f.norm());
      continue;
    }
    EXPECT_NEAR(ft.norm() / std::abs(f.dot(n)), o.friction, 1e-12);  // sliding: the Coulomb limit
    EXPECT_NEAR(ft.normalized().y(), spin > 0.0 ? -1.0 : 1.0, 1e-12);  // spin x (x - c) = -spin y for x - c = -x-hat
    EXPECT_LT(fd_error(c, x, d, tool), 1e-6);
  }
  // Sticking under a slow spin: the tangent check covers the stick branch too.
  ShellContact c(m, o);
  tool.spin = Eigen::Vector3d(0.0, 0.0, 1e-6);
  EXPECT_LT(fd_error(c, x, d, tool), 1e-6);
}

// The Phong surface: on a flat element with normal directors it is the flat facet; on four
// nodes of a sphere (radius 20, 6 degrees apart) with radial directors its points lie much
// closer to the sphere than the bilinear facet's (the facet sags by ~h^2 / (8 rho)).
TEST(ShellContact, PhongSurfaceFollowsTheDirectors) {
  ContactOptions flat, phong;
  phong.surface = ContactOptions::Surface::phong;
  NodeVectors x, d;
  const double xs[4] = {0, 1, 1, 0}, ys[4] = {0, 0, 1, 1};
  for (std::size_t I = 0; I < 4; ++I) {
    x[I] = Eigen::Vector3d(xs[I], ys[I], 0.0);
    d[I] = Eigen::Vector3d::UnitZ();
  }
  const Eigen::Vector4d N = element::quad_shape(0.3, -0.2);
  EXPECT_LT((ShellContact::surface_point(phong, N, x, d, 0.1) - ShellContact::surface_point(flat, N, x, d, 0.1)).norm(), 1e-15);
  const double rho = 20.0, a = 3.0 * M_PI / 180.0;
  for (std::size_t I = 0; I < 4; ++I) {
    const double th = (xs[I] - 0.5) * 2.0 * a, ph = (ys[I] - 0.5) * 2.0 * a;
    d[I] = Eigen::Vector3d(std::sin(th), std::sin(ph), 1.0).normalized();
    x[I] = rho * d[I];
  }
  double flat_gap = 0.0, phong_gap = 0.0;
  for (double xi : {-0.5, 0.0, 0.5})
    for (double eta : {-0.5, 0.0, 0.5}) {
      const Eigen::Vector4d n = element::quad_shape(xi, eta);
      flat_gap = std::max(flat_gap, std::abs(ShellContact::surface_point(flat, n, x, d, 0.0).norm() - rho));
      phong_gap = std::max(phong_gap, std::abs(ShellContact::surface_point(phong, n, x, d, 0.0).norm() - rho));
    }
  std::printf("distance from the sphere: flat facet %.3e mm, Phong %.3e mm\n", flat_gap, phong_gap);
  EXPECT_GT(flat_gap, 0.05);
  EXPECT_LT(phong_gap, 0.01 * flat_gap);
}

TEST(ShellContact, PenetrationOutsideTheToolGivesNothing) {
  OneElement s;
  ShellContact c(s.mesh, ContactOptions{});
  SphereTool tool;
  tool.centre = tool.centre_committed = Eigen::Vector3d(1.0, 0.0, 5.3);  // 0.05 mm above the top surface
  Vec24 r = Vec24::Zero();
  EXPECT_FALSE(c.element(0, s.x, s.d, s.x, s.d, 0.25, tool, &r, nullptr, nullptr));
  EXPECT_EQ(r.norm(), 0.0);
}

// A flat 10 x 10 mm element (tool side z = 0.25) and a 5 mm tool whose nose sinks 0.3 mm into
// its middle. The 2 x 2 points sit 2.89 mm from the middle in x and y: 4.08 mm off the tool
// axis, where the sphere is sqrt(25 - 16.7) = 2.88 mm above its nose, so they feel nothing; the
// middle point of 3 x 3 feels the 0.3 mm. surface_penetration finds the 0.3 mm in both cases.
TEST(ShellContact, SurfacePenetrationFindsAToolSunkBetweenThePoints) {
  const mesh::Mesh m = mesh::strip(10.0, 10.0, 1, 1);
  NodeVectors x, d;
  for (std::size_t i = 0; i < 4; ++i) {
    x[i] = m.nodes[static_cast<std::size_t>(m.quads[0][i])];
    d[i] = Eigen::Vector3d::UnitZ();
  }
  const Eigen::Vector3d middle = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  const double offset = 0.25, R = 5.0, depth = 0.3;
  SphereTool tool;
  tool.radius = R;
  tool.centre = tool.centre_committed = middle + Eigen::Vector3d(0.0, 0.0, offset + R - depth);
  for (int points : {2, 3}) {
    ContactOptions o;
    o.points = points;
    ShellContact c(m, o);
    Vec24 r = Vec24::Zero();
    ContactSummary cs;
    c.element(0, x, d, x, d, offset, tool, &r, nullptr, &cs);
    const double surface = ShellContact::surface_penetration(o, x, d, offset, tool);
    std::printf("%d x %d points: deepest point %.4f mm, %d active; surface %.4f mm\n", points, points, cs.max_penetration,
                cs.active_points, surface);
    EXPECT_NEAR(surface, depth, 1e-12);  // the grid (11 x 11) has the middle
    if (points == 2) {
      EXPECT_EQ(cs.active_points, 0);
      EXPECT_EQ(r.norm(), 0.0);
    } else {
      EXPECT_NEAR(cs.max_penetration, depth, 1e-12);
    }
  }
  // A tool that misses the element: 0; fewer than 2 samples: an error.
  tool.centre.z() += 1.0;
  EXPECT_EQ(ShellContact::surface_penetration(ContactOptions{}, x, d, offset, tool), 0.0);
  EXPECT_THROW(ShellContact::surface_penetration(ContactOptions{}, x, d, offset, tool, 1), std::invalid_argument);
}

// The cone scenes' summary warning: above 1.5x the points' depth, naming both depths and the
// point count; at or below it, nothing (the session-12 cone70 ratio 1.41 stays quiet).
TEST(ShellContact, ResolutionWarningAboveOneAndAHalfTimesThePointsDepth) {
  const std::string w = ShellContact::resolution_warning(0.177, 0.3, 2);
  std::printf("%s\n", w.c_str());
  EXPECT_NE(w.find("0.3 mm"), std::string::npos) << w;
  EXPECT_NE(w.find("2 x 2 contact points"), std::string::npos) << w;
  EXPECT_NE(w.find("0.177 mm"), std::string::npos) << w;
  EXPECT_NE(w.find("[contact] points"), std::string::npos) << w;
  EXPECT_EQ(ShellContact::resolution_warning(0.177, 0.250, 2), "");
  EXPECT_EQ(ShellContact::resolution_warning(0.2, 0.3, 3), "");       // exactly 1.5x
  EXPECT_NE(ShellContact::resolution_warning(0.2, 0.3001, 3), "");
  EXPECT_EQ(ShellContact::resolution_warning(0.0, 0.0, 2), "");       // no contact
}

// An elastic sheet (it cannot plough: no plastic wave ahead of the tool) indented 0.05 mm and
// dragged 6 mm: once sliding, the tool's horizontal force is mu times its vertical force
// (Coulomb), and zero at mu = 0. 0.5 mm elements and 3 x 3 contact points resolve the 0.7 mm
// contact patch.
double drag_ratio(double mu) {
  mesh::SquareSheetOptions so;
  so.length_x = so.length_y = 20.0;
  so.nx = so.ny = 40;
  const mesh::Mesh m = mesh::square_sheet(so);
  material::MaterialParams<double> stiff;
  stiff.E = 70000.0;
  stiff.nu = 0.3;
  stiff.plastic = false;
  model::ShellModel sheet(m, 1.0, stiff, {});
  ContactOptions co;
  co.penalty = 1000.0;
  co.friction = mu;
  co.points = 3;
  const double R = 5.0, top = 0.5, depth = 0.05;
  const model::ToolContact& tool = model::attach_tool(sheet, R, [=](double lambda) {
    const double press = std::min(lambda / 0.2, 1.0), travel = std::max(lambda - 0.2, 0.0) / 0.8;
    return Eigen::Vector3d(-3.0 + 6.0 * travel, 0.0, top + R - depth * press);
  }, co);
  solver::DofConstraints c(sheet.num_dofs());
  for (int n : m.node_sets.at("boundary"))
    for (int k = 0; k < 6; ++k) c.prescribe(model::ShellModel::dof(n, k));
  c.finalize();
  solver::NewtonOptions o;
  o.initial_increment = o.max_increment = 0.05;
  solver::NewtonSolver s(sheet, c, o);
  const auto r = s.solve();
  EXPECT_TRUE(r.converged) << r.message;
  const Eigen::Vector3d f = tool.force();
  const ContactSummary cs = tool.summary();
  std::printf("mu %.2f: tool force (%.5f, %.5f, %.5f) N, Fx/Fz %.5f, penetration %.5f mm, %d points, %d iterations\n", mu, f.x(),
              f.y(), f.z(), f.x() / f.z(), cs.max_penetration, cs.active_points, r.counters.iterations);
  EXPECT_GT(f.z(), 0.0);  // the sheet pushes the tool up
  return -f.x() / f.z();  // the sheet drags the tool back (-x) while it moves +x
}

TEST(ShellContact, DraggedToolFeelsCoulombFriction) {
  EXPECT_NEAR(drag_ratio(0.0), 0.0, 1e-3);  // ripple of the discrete contact points only
  EXPECT_NEAR(drag_ratio(0.05) / 0.05, 1.0, 0.02);
  EXPECT_NEAR(drag_ratio(0.15) / 0.15, 1.0, 0.02);
}

}  // namespace
}  // namespace spifit::contact
