#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <cstdlib>

namespace spifit::model {
namespace {

material::MaterialParams<double> elastic(double E, double nu) {
  material::MaterialParams<double> p;
  p.E = E;
  p.nu = nu;
  p.plastic = false;
  return p;
}

void clamp(const mesh::Mesh& m, const std::string& set, solver::DofConstraints* c) {
  for (int n : m.node_sets.at(set))
    for (int k = 0; k < 6; ++k) c->prescribe(ShellModel::dof(n, k));
}

TEST(Cantilever, TipShearMatchesBeamTheory) {
  const double L = 10.0, b = 1.0, t = 0.1, E = 1.2e6, P = 1e-3;
  const mesh::Mesh m = mesh::strip(L, b, 16, 2);
  ShellModel model(m, t, elastic(E, 0.0), {});
  solver::DofConstraints c(model.num_dofs());
  clamp(m, "clamped", &c);
  const auto& tip = m.node_sets.at("tip");
  for (int n : tip) model.add_nodal_load(ShellModel::dof(n, 2), P / static_cast<double>(tip.size()));
  c.finalize();
  solver::NewtonOptions o;
  o.initial_increment = o.max_increment = 1.0;
  solver::NewtonSolver s(model, c, o);
  const auto summary = s.solve();
  ASSERT_TRUE(summary.converged) << summary.message;
  const double I = b * t * t * t / 12.0;
  const double exact = P * L * L * L / (3.0 * E * I);  // shear deformation negligible (L/t = 100)
  const double w = model.displacement(m.node_sets.at("tip_centre")[0]).z();
  std::printf("tip deflection %.6g, beam theory %.6g, iterations %d\n", w, exact, summary.iterations);
  EXPECT_NEAR(w / exact, 1.0, 0.01);
}

TEST(Cantilever, EndMomentRollsTheStripIntoACircle) {
  const double L = 12.0, b = 1.0, t = 0.1, E = 1.2e6;
  const mesh::Mesh m = mesh::strip(L, b, getenv("NEL") ? atoi(getenv("NEL")) : 16, 1);
  ShellModel model(m, t, elastic(E, 0.0), {});
  solver::DofConstraints c(model.num_dofs());
  clamp(m, "clamped", &c);
  const double I = b * t * t * t / 12.0;
  const double M = 2.0 * std::numbers::pi * E * I / L;  // curvature 2 pi / L: a full circle
  const auto& tip = m.node_sets.at("tip");
  for (int n : tip) model.add_nodal_load(ShellModel::dof(n, 4), -M / static_cast<double>(tip.size()));
  c.finalize();
  solver::NewtonOptions o;
  o.initial_increment = 0.05;
  o.max_increment = 0.1;
  if (getenv("NOLS")) o.line_search = false;
  solver::NewtonSolver s(model, c, o);
  const auto summary = s.solve(1.0, [](const solver::IncrementReport& r) {
    if (r.index <= 3 || r.index % 10 == 0) {
      std::printf("inc %d lambda %.4f it %d ls %d:", r.index, r.lambda, r.iterations, r.line_searches);
      for (double v : r.residual_norms) std::printf(" %.2e", v);
      std::printf("\n");
    }
    return true;
  });
  ASSERT_TRUE(summary.converged) << summary.message;
  for (int n : tip) {
    const Eigen::Vector3d x = model.position(n);
    std::printf("tip node at (%.3e, %.3e, %.3e)\n", x.x(), x.y(), x.z());
    EXPECT_LT(std::hypot(x.x(), x.z()), 1e-3 * L);
  }
  std::printf("roll-up: %d increments, %d iterations\n", summary.increments, summary.iterations);
}

}  // namespace
}  // namespace spifit::model
