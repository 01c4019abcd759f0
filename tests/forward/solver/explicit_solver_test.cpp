// The explicit scheme against closed forms: the first axial mode of a fixed-free bar and the
// first bending mode of a simply supported square plate (period and energy), and the stable
// step of the lumped mass (a bar's element bound is h / c exactly).
#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/explicit_mass.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/material/material_card.hpp"
#include "forward/solver/explicit_solver.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

namespace spifit::solver {
namespace {

constexpr double kDensity = 2.7e-9;  // t/mm^3

material::MaterialParams<double> elastic(double nu) {
  material::MaterialParams<double> p;
  p.E = 70000.0;
  p.nu = nu;
  p.plastic = false;
  return p;
}

// Times where a sampled series crosses zero going up or down (linear between samples).
std::vector<double> zero_crossings(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> z;
  for (std::size_t i = 1; i < y.size(); ++i)
    if ((y[i - 1] < 0.0) != (y[i] < 0.0)) z.push_back(t[i - 1] + (t[i] - t[i - 1]) * y[i - 1] / (y[i - 1] - y[i]));
  return z;
}

// Mean period from the zero crossings after the first (each half period apart).
double period(const std::vector<double>& z) {
  return 2.0 * (z.back() - z.front()) / static_cast<double>(z.size() - 1);
}

TEST(ExplicitSolver, BarFirstAxialModeHasTheClosedFormPeriodAndKeepsItsEnergy) {
  const double L = 100.0, c = std::sqrt(70000.0 / kDensity);
  const int n = 40;
  const mesh::Mesh m = mesh::strip(L, 2.5, n, 1);
  model::ShellModel sm(m, 1.0, elastic(0.0), {});
  DofConstraints cons(sm.num_dofs());
  for (int node = 0; node < sm.num_nodes(); ++node)
    for (int k = 0; k < 6; ++k)
      if (k != 0 || m.nodes[static_cast<std::size_t>(node)].x() < 1e-9) cons.prescribe(model::ShellModel::dof(node, k));
  cons.finalize();
  model::ExplicitMassInputs in;
  in.density = kDensity;
  const model::ExplicitMass mass = model::explicit_mass(sm, in);
  // The element bound is below the 1D bar's h / c (the element's own membrane modes are
  // stiffer than the bar's), but not far.
  const double h = L / n;
  EXPECT_LT(mass.time_step / in.options.safety, h / c);
  EXPECT_GT(mass.time_step / in.options.safety, 0.5 * h / c);

  ExplicitSolver solver(sm, cons, mass.diagonal, in.options);
  const double v0 = 10.0, k = std::numbers::pi / (2.0 * L), omega = k * c;
  for (int node = 0; node < sm.num_nodes(); ++node) {
    const auto terms = cons.expansion(model::ShellModel::dof(node, 0));
    if (!terms.empty()) solver.velocity()(terms[0].reduced) = v0 * std::sin(k * m.nodes[static_cast<std::size_t>(node)].x());
  }
  const double e0 = solver.kinetic_energy();
  const int tip = m.node_sets.at("tip")[0];
  const double periods = 2.0, duration = periods * 2.0 * std::numbers::pi / omega;
  std::vector<double> t, u;
  double worst_balance = 0.0;
  ExplicitSchedule s;
  s.duration = duration;
  s.output_interval = 1.0 / 400.0;
  const ExplicitSummary r = solver.run(s, [&] { return mass.time_step; }, {}, [&](const ExplicitInterval& iv) {
    t.push_back(iv.time);
    u.push_back(sm.displacement(tip).x());
    const double total = iv.kinetic + model::energy_account(sm).internal();
    worst_balance = std::max(worst_balance, std::abs(total - e0) / e0);
    return true;
  });
  ASSERT_TRUE(r.completed) << r.message;
  const std::vector<double> z = zero_crossings(t, u);
  ASSERT_GE(z.size(), 3u);
  const double expected = 2.0 * std::numbers::pi / omega;  // 4 L / c
  EXPECT_NEAR(period(z) / expected, 1.0, 2e-3) << "period " << period(z) << " s, closed form " << expected << " s";
  double peak = 0.0;
  for (double x : u) peak = std::max(peak, std::abs(x));
  EXPECT_NEAR(peak / (v0 / omega), 1.0, 5e-3);
  EXPECT_LT(worst_balance, 1e-3);
}

TEST(ExplicitSolver, SimplySupportedPlateFirstBendingModeHasTheKirchhoffPeriod) {
  const double a = 100.0, t = 1.0, nu = 0.3;
  mesh::SquareSheetOptions o;
  o.length_x = o.length_y = a;
  o.nx = o.ny = 10;
  const mesh::Mesh m = mesh::square_sheet(o);
  model::ShellModel sm(m, t, elastic(nu), {});
  DofConstraints cons(sm.num_dofs());
  for (int node : m.node_sets.at("boundary"))
    for (int k = 0; k < 3; ++k) cons.prescribe(model::ShellModel::dof(node, k));
  cons.finalize();
  model::ExplicitMassInputs in;
  in.density = kDensity;
  const model::ExplicitMass mass = model::explicit_mass(sm, in);
  ExplicitSolver solver(sm, cons, mass.diagonal, in.options);
  const double D = 70000.0 * t * t * t / (12.0 * (1.0 - nu * nu));
  const double omega = std::numbers::pi * std::numbers::pi * 2.0 / (a * a) * std::sqrt(D / (kDensity * t));
  const double v0 = 1e-3 * omega;  // deflection amplitude 1e-3 t: linear
  const double p = std::numbers::pi / a;
  for (int node = 0; node < sm.num_nodes(); ++node) {
    const double x = m.nodes[static_cast<std::size_t>(node)].x() + 0.5 * a, y = m.nodes[static_cast<std::size_t>(node)].y() + 0.5 * a;
    const double w[3] = {v0 * std::sin(p * x) * std::sin(p * y), v0 * p * std::sin(p * x) * std::cos(p * y),
                         -v0 * p * std::cos(p * x) * std::sin(p * y)};  // w', and the rotation rates d(w')/dy, -d(w')/dx
    const int dofs[3] = {2, 3, 4};
    for (int i = 0; i < 3; ++i) {
      const auto terms = cons.expansion(model::ShellModel::dof(node, dofs[i]));
      if (!terms.empty()) solver.velocity()(terms[0].reduced) = w[i];
    }
  }
  const int centre = m.node_sets.at("centre")[0];
  std::vector<double> tt, wc;
  ExplicitSchedule s;
  s.duration = 2.2 * 2.0 * std::numbers::pi / omega;
  s.output_interval = 1.0 / 300.0;
  const ExplicitSummary r = solver.run(s, [&] { return mass.time_step; }, {}, [&](const ExplicitInterval& iv) {
    tt.push_back(iv.time);
    wc.push_back(sm.displacement(centre).z());
    return true;
  });
  ASSERT_TRUE(r.completed) << r.message;
  const std::vector<double> z = zero_crossings(tt, wc);
  ASSERT_GE(z.size(), 3u);
  const double expected = 2.0 * std::numbers::pi / omega;
  EXPECT_NEAR(period(z) / expected, 1.0, 0.02) << "period " << period(z) << " s, Kirchhoff " << expected << " s";
}

}  // namespace
}  // namespace spifit::solver

namespace spifit::solver {
namespace {

// The centre node of a clamped square sheet pushed down 2 mm (the explicit-stability study of
// thesis §7.2, Table 7.2, at the thickness the thesis could not run: t/l = 1, where LAGAMINE
// needed t/l <= 0.4), elastic-plastic card C.3 + C.4, with mass scaling 1e5 against the
// implicit (static) solution of the same model: the deflection along y = 0.
struct PushedSheet {
  mesh::Mesh mesh;
  std::unique_ptr<model::ShellModel> model;
  std::unique_ptr<DofConstraints> cons;
  explicit PushedSheet(double thickness) {
    mesh::SquareSheetOptions o;
    o.length_x = o.length_y = 40.0;
    o.nx = o.ny = 16;  // l = 2.5 mm
    mesh = mesh::square_sheet(o);
    const auto card = material::load_material_card(std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c3c4.toml");
    model::ShellModelOptions mo;
    mo.shell.thickness_points = 5;
    model = std::make_unique<model::ShellModel>(mesh, thickness, card.params, mo);
    cons = std::make_unique<DofConstraints>(model->num_dofs());
    for (int n : mesh.node_sets.at("boundary"))
      for (int k = 0; k < 6; ++k) cons->prescribe(model::ShellModel::dof(n, k));
    cons->prescribe(model::ShellModel::dof(mesh.node_sets.at("centre")[0], 2), -2.0);
    model->use_nodal_rotation_frames(cons.get());
    cons->finalize();
  }
  // z of the nodes on y = 0, by x.
  std::vector<std::pair<double, double>> row() const {
    std::vector<std::pair<double, double>> r;
    for (int n = 0; n < model->num_nodes(); ++n)
      if (std::abs(mesh.nodes[static_cast<std::size_t>(n)].y()) < 1e-9) r.push_back({mesh.nodes[static_cast<std::size_t>(n)].x(), model->position(n).z()});
    std::sort(r.begin(), r.end());
    return r;
  }
};

TEST(ExplicitSolver, ThickSheetPushedAtItsCentreIsStableAtOneThicknessPerElementLength) {
  const double t = 2.5;  // t/l = 1
  PushedSheet implicit(t);
  NewtonOptions no;
  no.initial_increment = no.max_increment = 0.05;
  NewtonSolver newton(*implicit.model, *implicit.cons, no);
  ASSERT_TRUE(newton.solve(0.0, 1.0, {}).converged);

  PushedSheet dyn(t);
  ExplicitOptions eo;
  eo.mass_scaling = 1e5;
  model::ExplicitMassInputs in;
  in.options = eo;
  const model::ExplicitMass mass = model::explicit_mass(*dyn.model, in);
  ExplicitSolver solver(*dyn.model, *dyn.cons, mass.diagonal, eo);
  ExplicitSchedule s;
  s.duration = 0.5;
  s.output_interval = 0.05;
  const ExplicitSummary r = solver.run(s, [&] { return model::current_time_step(*dyn.model, mass, eo.safety); }, {}, {});
  ASSERT_TRUE(r.completed) << r.message;
  const auto a = implicit.row(), b = dyn.row();
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0, worst_kink = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(a[i].second - b[i].second));
    if (i > 0 && i + 1 < a.size()) {  // the accordion mode: a zigzag the implicit shape does not have
      const double ka = a[i - 1].second - 2.0 * a[i].second + a[i + 1].second, kb = b[i - 1].second - 2.0 * b[i].second + b[i + 1].second;
      worst_kink = std::max(worst_kink, std::abs(ka - kb));
    }
  }
  // Measured: 4 560 steps, deflection within 0.0011 mm, second differences within 0.0012 mm.
  EXPECT_LT(worst, 0.05);
  EXPECT_LT(worst_kink, 0.05);
}

}  // namespace
}  // namespace spifit::solver
