// Direct differentiation through a shell model with a tool (FeModel::enable_sensitivities and
// the Newton solver's sensitivity step): the derivatives of the tool force along a plastic
// indentation against central differences of whole runs with perturbed parameters.
#include "forward/material/material_card.hpp"
#include "forward/material/material_inputs.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/model/tool_contact.hpp"
#include "forward/solver/newton_solver.hpp"
#include "tests/support/central_differences.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace spifit::model {
namespace {

using material::FieldSeed;
using material::SensitivityRow;

constexpr int kCount = 5;  // swift.K, swift.n, E, hill.G (with H = 2 - G), the contact penalty

SensitivityRow unit(int k) {
  SensitivityRow r = SensitivityRow::Zero();
  r(k) = 1.0;
  return r;
}

const material::MaterialInput& input(const char* name) { return *material::find_material_input(name); }

std::vector<FieldSeed> seeds() {
  return {{input("swift.K").field, unit(0)}, {input("swift.n").field, unit(1)}, {input("elastic.E").field, unit(2)},
          {input("hill.G").field, unit(3)}, {input("hill.H").field, -unit(3)}};
}

material::MaterialParams<double> card() {
  return material::load_material_card(std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c3c4.toml").params;
}

// One run of a clamped 10 x 10 x 0.5 mm sheet (8 x 8 shells, 3 thickness points) under an R 3
// tool: the force on the tool, the contact's summary and the force's derivatives per increment.
struct SheetRun {
  std::vector<Eigen::Vector3d> force;
  std::vector<contact::ContactSummary> contact;
  std::vector<Eigen::Matrix<double, 3, Eigen::Dynamic>> sensitivity;
};

struct SheetSetup {
  contact::ContactOptions contact;
  std::function<Eigen::Vector3d(double)> centre;  // the tool's centre against the load factor
  int increments = 10;                            // equal, converged to 1e-11
  double hourglass = 0.0;                         // > 0: the one-point shell
  bool robust = false;                            // line search, 40 iterations, no divergence rule
  // With sensitivities: the card's seeds in `count` slots, the contact's own slots.
  std::vector<FieldSeed> seeds;
  int count = 0;
  contact::ShellContact::ParameterSlots slots;
};

constexpr double kToolRadius = 3.0;

SheetRun run_sheet(const material::MaterialParams<double>& p, const SheetSetup& setup) {
  mesh::SquareSheetOptions so;
  so.length_x = so.length_y = 10.0;
  so.nx = so.ny = 8;
  const mesh::Mesh mesh = mesh::square_sheet(so);
  ShellModelOptions mo;
  mo.shell.thickness_points = 3;
  mo.shell.hourglass_stiffness = setup.hourglass;
  ShellModel model(mesh, 0.5, p, mo);
  ToolContact& tool = attach_tool(model, kToolRadius, setup.centre, setup.contact);
  solver::DofConstraints c(model.num_dofs());
  for (int n : mesh.node_sets.at("boundary"))
    for (int k = 0; k < 6; ++k) c.prescribe(ShellModel::dof(n, k));
  c.finalize();
  if (setup.count > 0) {
    tool.set_parameter_slots(setup.slots);
    model.enable_sensitivities(setup.seeds, setup.count, p);
  }
  solver::NewtonOptions o;
  o.initial_increment = o.max_increment = o.min_increment = 1.0 / setup.increments;
  o.force_tolerance = o.displacement_tolerance = 1e-11;
  if (setup.robust) {
    o.line_search = true;
    o.max_iterations = 40;
    o.divergence_after = 0;
  }
  solver::NewtonSolver s(model, c, o);
  SheetRun run;
  const solver::NewtonSummary sum = s.solve(1.0, [&](const solver::IncrementReport&) {
    run.force.push_back(tool.force());
    run.contact.push_back(tool.summary());
    run.sensitivity.push_back(model.contribution_force_sensitivity());
    return true;
  });
  EXPECT_TRUE(sum.converged) << sum.message;
  return run;
}

// The sheet indented 1.2 mm in ten equal increments.
SheetRun indent(const material::MaterialParams<double>& p, bool sensitivities, double penalty = 1000.0, double hourglass = 0.0) {
  SheetSetup setup;
  setup.hourglass = hourglass;
  setup.robust = hourglass > 0.0;  // the one-point sheet needs the line search at 0.6 mm and beyond
  setup.contact.penalty = penalty;
  setup.centre = [](double lambda) { return Eigen::Vector3d(0.3, -0.2, 0.25 + kToolRadius - 1.2 * lambda); };
  if (sensitivities) {
    setup.seeds = seeds();
    setup.count = kCount;
    setup.slots.penalty = 4;
  }
  return run_sheet(p, setup);
}

void expect_indent_derivatives_match(double hourglass) {
  const material::MaterialParams<double> p = card();
  const SheetRun ddm = indent(p, true, 1000.0, hourglass);
  ASSERT_EQ(ddm.force.size(), 10u);
  const SheetRun plain = indent(p, false, 1000.0, hourglass);
  for (std::size_t n = 0; n < ddm.force.size(); ++n) EXPECT_EQ(ddm.force[n], plain.force[n]) << "increment " << n;
  const std::vector<FieldSeed> sd = seeds();
  const char* names[kCount] = {"swift.K", "swift.n", "elastic.E", "hill.G", "contact.penalty"};
  // Steps small enough that no contact point or layer switches state between the runs + h
  // and - h: with steps 64 times larger, central differences straddle such switches and lie up
  // to 3e-4 (relative) off, and they converge to the exact values as the steps shrink.
  const double steps[kCount] = {1.0 / 64.0, 2e-3 / 64.0, 100.0 / 64.0, 2e-3 / 64.0, 1000.0 / 6400.0};
  for (int k = 0; k < kCount; ++k) {
    std::vector<Eigen::Vector3d> cd(10), cd4(10);
    for (double step : {steps[k], steps[k] / 4.0}) {
      material::MaterialParams<double> pp = p, pm = p;
      double kp = 1000.0, km = 1000.0;
      if (k == 4) {
        kp += step;
        km -= step;
      } else {
        material::set_material_input(pp, input(names[k]), material::material_field(p, input(names[k]).field) + step);
        material::set_material_input(pm, input(names[k]), material::material_field(p, input(names[k]).field) - step);
      }
      if (k == 3) {
        pp.H = 2.0 - pp.G;
        pm.H = 2.0 - pm.G;
      }
      const SheetRun rp = indent(pp, false, kp, hourglass), rm = indent(pm, false, km, hourglass);
      for (std::size_t n = 0; n < 10; ++n) (step == steps[k] ? cd : cd4)[n] = (rp.force[n] - rm.force[n]) / (2.0 * step);
    }
    std::vector<Eigen::Vector3d> exact;
    for (const auto& d : ddm.sensitivity) exact.push_back(d.col(k));
    const double worst = test::expect_within_central_differences(exact, cd, cd4, 1e-6, names[k]);
    std::printf("%s: largest relative difference to central differences (h/4) %.2e\n", names[k], worst);
  }
}

TEST(ShellModelSensitivity, ToolForceDerivativesMatchCentralDifferences) { expect_indent_derivatives_match(0.0); }

// The one-point shell: its centre's section carries the thickness and the contact's offset, and
// the hourglass stiffness follows E.
TEST(ShellModelSensitivity, OnePointShellToolForceDerivativesMatchCentralDifferences) { expect_indent_derivatives_match(0.03); }

// The indentation continued by a drag: pressed 0.8 mm into the sheet in 8 increments, then moved
// 1 mm along x in 16 more, with Coulomb friction: the stick history (the committed tangential
// tractions) carries derivatives from increment to increment.
constexpr double kDrag = 1.0;  // mm
constexpr int kDragIncrements = 24;

SheetRun drag(const material::MaterialParams<double>& p, double penalty, double mu, double tangential_penalty, bool sensitivities,
             contact::ContactOptions::Surface surface = contact::ContactOptions::Surface::flat) {
  SheetSetup setup;
  setup.contact.surface = surface;
  setup.contact.penalty = penalty;
  setup.contact.friction = mu;
  setup.contact.tangential_penalty = tangential_penalty;
  setup.centre = [](double lambda) {
    const double press = std::min(lambda, 1.0 / 3.0) * 3.0, move = std::max(lambda - 1.0 / 3.0, 0.0) * 1.5;
    return Eigen::Vector3d(-0.5 + kDrag * move, 0.1, 0.25 + kToolRadius - 0.8 * press);
  };
  setup.increments = kDragIncrements;
  setup.robust = true;
  if (sensitivities) {
    setup.seeds = {{input("swift.K").field, unit(0)}};
    setup.count = 3;
    setup.slots = {.penalty = 1, .friction = 2};
  }
  return run_sheet(p, setup);
}

// With K_t = K_p every point slides during the drag (each increment's slip, 0.06 mm, exceeds
// mu p / K_t); with K_t = K_p / 10 and mu = 0.3 some stick (and all of them during the press,
// where the force then does not depend on mu). The penalty moves K_t too in the first.
// The drag's derivatives against central differences, on the given contact surface.
void expect_drag_derivatives_match(contact::ContactOptions::Surface surface) {
  const material::MaterialParams<double> p = card();
  const double penalty = 1000.0;
  struct Variant {
    double mu, tangential_penalty;
    bool sticks;
  };
  for (const Variant v : {Variant{0.15, 0.0, false}, Variant{0.3, 100.0, true}}) {
    const SheetRun ddm = drag(p, penalty, v.mu, v.tangential_penalty, true, surface);
    ASSERT_EQ(ddm.force.size(), static_cast<std::size_t>(kDragIncrements));
    const SheetRun plain = drag(p, penalty, v.mu, v.tangential_penalty, false, surface);
    for (std::size_t n = 0; n < ddm.force.size(); ++n) EXPECT_EQ(ddm.force[n], plain.force[n]) << "increment " << n;
    EXPECT_GT(std::abs(ddm.force.back().x()), 0.05 * std::abs(ddm.force.back().z()));  // friction drags the tool
    int sticking = 0, sliding = 0;  // point-increments of the drag
    for (std::size_t n = kDragIncrements / 3; n < ddm.contact.size(); ++n) {
      sticking += ddm.contact[n].sticking_points;
      sliding += ddm.contact[n].active_points - ddm.contact[n].sticking_points;
    }
    std::printf("mu %.2f, K_t %g: %d sticking and %d sliding point-increments in the drag\n", v.mu, v.tangential_penalty, sticking, sliding);
    EXPECT_EQ(sticking > 0, v.sticks);
    EXPECT_GT(sliding, 0);
    const char* names[3] = {"swift.K", "contact.penalty", "contact.friction"};
    const double steps[3] = {1.0 / 64.0, penalty / 6400.0, v.mu / 6400.0};
    for (int k = 0; k < 3; ++k) {
      std::vector<Eigen::Vector3d> cd(kDragIncrements), cd4(kDragIncrements);
      for (double step : {steps[k], steps[k] / 4.0}) {
        material::MaterialParams<double> pp = p, pm = p;
        if (k == 0) {
          material::set_material_input(pp, input("swift.K"), material::material_field(p, input("swift.K").field) + step);
          material::set_material_input(pm, input("swift.K"), material::material_field(p, input("swift.K").field) - step);
        }
        const SheetRun rp = drag(pp, penalty + (k == 1 ? step : 0.0), v.mu + (k == 2 ? step : 0.0), v.tangential_penalty, false, surface);
        const SheetRun rm = drag(pm, penalty - (k == 1 ? step : 0.0), v.mu - (k == 2 ? step : 0.0), v.tangential_penalty, false, surface);
        for (std::size_t n = 0; n < cd.size(); ++n) (step == steps[k] ? cd : cd4)[n] = (rp.force[n] - rm.force[n]) / (2.0 * step);
      }
      std::vector<Eigen::Vector3d> exact;
      for (const auto& d : ddm.sensitivity) exact.push_back(d.col(k));
      // Relative to the path's largest derivative: dF/dmu vanishes while every point sticks.
      double path_scale = 0.0;
      for (const auto& c : cd4) path_scale = std::max(path_scale, c.cwiseAbs().maxCoeff());
      const double worst = test::expect_within_central_differences(exact, cd, cd4, 1e-6, names[k], 1e-3 * path_scale);
      std::printf("  %s: largest relative difference to central differences (h/4) %.2e\n", names[k], worst);
    }
  }
}

TEST(ShellModelSensitivity, FrictionDerivativesMatchCentralDifferences) { expect_drag_derivatives_match(contact::ContactOptions::Surface::flat); }

// The curved (Phong) surface moves its contact points with the directors and the thickness as
// well: the forces' distribution to the nodes (J^T f) carries derivatives of its own.
TEST(ShellModelSensitivity, PhongSurfaceDerivativesMatchCentralDifferences) {
  expect_drag_derivatives_match(contact::ContactOptions::Surface::phong);
}

TEST(ShellModelSensitivity, RefusesMoreThanEightParametersOnly) {
  mesh::SquareSheetOptions so;
  so.nx = so.ny = 2;
  const mesh::Mesh mesh = mesh::square_sheet(so);
  const material::MaterialParams<double> p = card();
  auto refusal = [&](const ShellModelOptions& mo, const contact::ContactOptions& co, int count) {
    ShellModel model(mesh, 0.5, p, mo);
    attach_tool(model, 3.0, [](double) { return Eigen::Vector3d(0.0, 0.0, 10.0); }, co);
    try {
      model.enable_sensitivities(seeds(), count, p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  contact::ContactOptions phong;
  phong.surface = contact::ContactOptions::Surface::phong;
  EXPECT_EQ(refusal({}, phong, kCount), "");
  ShellModelOptions one_point;
  one_point.shell.hourglass_stiffness = 0.03;
  EXPECT_EQ(refusal(one_point, {}, kCount), "");
  EXPECT_NE(refusal({}, {}, 9).find("1 to 8"), std::string::npos);
  EXPECT_EQ(refusal({}, {}, kCount), "");
}

}  // namespace
}  // namespace spifit::model
