#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/mesh/benchmark_meshes.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/lumped_mass.hpp"
#include "forward/model/model_vtu.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/benchmark/shell_benchmarks.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

namespace spifit::model {
namespace {

material::MaterialParams<double> steel() {
  material::MaterialParams<double> p;
  p.E = 210000.0; p.nu = 0.3; p.plastic = false;
  return p;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ShellModel, DegenerateElementsAreErrorsNamingTheElement) {
  mesh::Mesh m = mesh::strip(4.0, 1.0, 4, 1);
  m.nodes[7] = m.nodes[2];  // element 1 and 2 collapse an edge
  const std::string err = error_of([&] { ShellModel sm(m, 0.1, steel(), {}); });
  EXPECT_NE(err.find("element 1"), std::string::npos) << err;
  mesh::Mesh flat = mesh::strip(4.0, 1.0, 4, 1);
  for (auto& p : flat.nodes) p.y() = 0.0;  // zero area everywhere
  EXPECT_NE(error_of([&] { ShellModel sm(flat, 0.1, steel(), {}); }), "");
}

TEST(ShellModel, InconsistentOrientationAndDrillingMomentsAreErrors) {
  mesh::Mesh m = mesh::strip(4.0, 1.0, 4, 1);
  std::swap(m.quads[2][1], m.quads[2][3]);  // element 2 numbered clockwise: its normal is -z
  EXPECT_NE(error_of([&] { ShellModel sm(m, 0.1, steel(), {}); }).find("orientation"), std::string::npos);
  const mesh::Mesh flat = mesh::strip(4.0, 1.0, 4, 1);
  ShellModel sm(flat, 0.1, steel(), {});
  EXPECT_NE(error_of([&] { sm.add_nodal_load(ShellModel::dof(3, 5), 1.0); }).find("drilling"), std::string::npos);
  EXPECT_EQ(error_of([&] { sm.add_nodal_load(ShellModel::dof(3, 4), 1.0); }), "");  // bending moment: fine
}

TEST(ShellModel, ThicknessOverLengthWarnsAboveOneAndRefusesAboveThree) {
  const mesh::Mesh m = mesh::strip(10.0, 1.0, 10, 1);  // 1 mm elements
  ShellModel ok(m, 0.5, steel(), {});
  EXPECT_TRUE(ok.warnings().empty());
  ShellModel warned(m, 1.7, steel(), {});  // the thesis's fine cone mesh
  ASSERT_EQ(warned.warnings().size(), 1u);
  EXPECT_NE(warned.warnings()[0].find("t/l = 1.7"), std::string::npos) << warned.warnings()[0];
  const std::string err = error_of([&] { ShellModel sm(m, 3.5, steel(), {}); });
  EXPECT_NE(err.find("t/l = 3.5"), std::string::npos) << err;
}

TEST(ShellModel, UnsupportedThicknessPointCountIsAnError) {
  const mesh::Mesh m = mesh::strip(10.0, 1.0, 10, 1);
  ShellModelOptions o;
  o.shell.thickness_points = 12;
  EXPECT_NE(error_of([&] { ShellModel sm(m, 0.5, steel(), o); }).find("thickness points"), std::string::npos);
}

TEST(ShellModel, LumpedMassAddsUpToThePlateMass) {
  mesh::SquareSheetOptions so;
  so.length_x = so.length_y = 100.0;
  so.nx = so.ny = 10;
  const mesh::Mesh m = mesh::square_sheet(so);
  ShellModel sm(m, 1.2, steel(), {});
  const auto mass = model::lumped_mass(sm, 2.7e-9);
  const double total = std::accumulate(mass.translational.begin(), mass.translational.end(), 0.0);
  EXPECT_NEAR(total / (2.7e-9 * 1.2 * 100.0 * 100.0), 1.0, 1e-13);
  // Corner node: a quarter of one element (10 x 10 mm); thesis eq. 6.62: c = max(t^2/12, S/18) = S/18.
  const int corner = 0;
  EXPECT_NEAR(mass.translational[corner] / (2.7e-9 * 1.2 * 100.0 / 4.0), 1.0, 1e-13);
  EXPECT_NEAR(mass.rotational[corner] / (mass.translational[corner] * 100.0 / 18.0), 1.0, 1e-13);
  EXPECT_NEAR(mass.drilling[corner] / mass.rotational[corner], 2.0, 1e-13);
}

TEST(ShellModel, VtuFrameHasEveryArrayAtTheRightSize) {
  const mesh::Mesh m = mesh::strip(10.0, 1.0, 10, 2);
  ShellModel sm(m, 0.5, steel(), {});
  const mesh::VtuFrame f = model::vtu_frame(sm);
  ASSERT_EQ(f.point_data.size(), 3u);
  for (const auto& a : f.point_data) EXPECT_EQ(a.values.size(), static_cast<std::size_t>(a.components * m.num_nodes())) << a.name;
  ASSERT_EQ(f.cell_data.size(), 4u);
  for (const auto& a : f.cell_data) EXPECT_EQ(a.values.size(), static_cast<std::size_t>(a.components * m.num_elements())) << a.name;
}

TEST(ShellModel, CholmodAndUmfpackAgreeOnASymmetricProblem) {
  double values[2];
  for (int k = 0; k < 2; ++k) {
    scene::ShellBenchmark b = scene::make_shell_benchmark({"pinched_hemisphere", 8, 5});
    b.solver.linear_solver = k == 0 ? solver::LinearSolverKind::umfpack : solver::LinearSolverKind::cholmod;
    solver::NewtonSolver s(*b.model, *b.constraints, b.solver);
    const auto r = s.solve();
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_EQ(r.counters.symbolic_analyses, 1);
    values[k] = b.value(*b.model);
  }
  EXPECT_NEAR(values[1] / values[0], 1.0, 1e-9);
}

TEST(ShellModel, AutomaticLinearSolverFollowsTheTangentsSymmetry) {
  // Elastic hemisphere: symmetric tangent, CHOLMOD only.
  scene::ShellBenchmark b = scene::make_shell_benchmark({"pinched_hemisphere", 8, 5});
  solver::NewtonSolver s(*b.model, *b.constraints, b.solver);
  const auto r = s.solve();
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_GE(r.counters.cholmod_factorisations, 1);
  EXPECT_EQ(r.counters.umfpack_factorisations, 0);
  // Hill + Armstrong-Frederick (card C.7): the consistent tangent is non-symmetric once
  // plastic, and UMFPACK takes over.
  const mesh::Mesh m = mesh::strip(10.0, 1.0, 10, 1);
  material::MaterialParams<double> af;
  af.F = 1.224; af.G = 1.193; af.H = 0.807; af.N = af.L = af.M = 4.06;
  af.hardening[material::SwiftHardening::K] = 111.0; af.hardening[material::SwiftHardening::eps0] = 5e-4; af.hardening[material::SwiftHardening::n] = 0.266;
  af.kinematic = material::make_kinematic<material::ArmstrongFrederick>({51.4, 46.0});
  ShellModel model(m, 1.0, af, {});
  solver::DofConstraints c(model.num_dofs());
  for (int n : m.node_sets.at("clamped"))
    for (int k = 0; k < 6; ++k) c.prescribe(ShellModel::dof(n, k));
  for (int n : m.node_sets.at("tip")) c.prescribe(ShellModel::dof(n, 0), 0.2);  // 2 % stretch
  c.finalize();
  solver::NewtonOptions o;
  o.initial_increment = 0.25;
  solver::NewtonSolver s2(model, c, o);
  const auto r2 = s2.solve();
  ASSERT_TRUE(r2.converged) << r2.message;
  EXPECT_GT(r2.counters.umfpack_factorisations, 0);
}

// Nodal rotation frames (use_nodal_rotation_frames): which nodes get one, the frame itself,
// and the forces the model hands out in and out of the frames.
TEST(ShellModel, RotationFramesFollowTheDirectorAndKeepResultsInXyz) {
  const mesh::Mesh m = mesh::strip(4.0, 1.0, 4, 1);  // 10 nodes, two clamped
  ShellModel plain(m, 0.1, steel(), {}), framed(m, 0.1, steel(), {});
  solver::DofConstraints c(framed.num_dofs());
  for (int n : m.node_sets.at("clamped"))
    for (int k = 0; k < 6; ++k) c.prescribe(ShellModel::dof(n, k));
  c.tie(ShellModel::dof(9, 4), {{ShellModel::dof(7, 4), 1.0}});  // node 9 tied, node 7 its master
  EXPECT_EQ(framed.use_nodal_rotation_frames(&c), 10 - 2 - 2);
  for (int n : m.node_sets.at("clamped")) EXPECT_FALSE(framed.has_rotation_frame(n));
  EXPECT_FALSE(framed.has_rotation_frame(9));
  EXPECT_FALSE(framed.has_rotation_frame(7));
  EXPECT_TRUE(framed.has_rotation_frame(6));
  EXPECT_TRUE(c.prescribed(ShellModel::dof(6, 5)));  // the drilling unknown left the system
  EXPECT_FALSE(c.prescribed(ShellModel::dof(6, 4)));
  EXPECT_NE(framed.describe_dof(ShellModel::dof(6, 3)).find("rotation t1 (nodal frame)"), std::string::npos);
  EXPECT_NE(framed.describe_dof(ShellModel::dof(9, 3)).find("rotation x"), std::string::npos);
  c.finalize();
  EXPECT_THROW(framed.use_nodal_rotation_frames(&c), std::logic_error);
  solver::DofConstraints wrong(12);
  EXPECT_THROW(framed.use_nodal_rotation_frames(&wrong), std::invalid_argument);

  // The frame: orthonormal, third column the director itself, the global axes on the flat
  // sheet, and carried rigidly by a rotation normal to the reference director.
  const Eigen::Vector3d d0 = framed.reference_director(6);
  const Eigen::Matrix3d q0 = framed.rotation_frame(6, d0);
  EXPECT_LT((q0.cwiseAbs() - Eigen::Matrix3d::Identity()).norm(), 1e-15) << q0;
  const Eigen::Vector3d psi(0.3, -0.7, 0.0);  // normal to d0 = +-z
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(psi.norm(), psi.normalized()).toRotationMatrix();
  const Eigen::Matrix3d q = framed.rotation_frame(6, rot * d0);
  EXPECT_LT((q - rot * q0).norm(), 1e-14);
  for (const Eigen::Vector3d& d : {Eigen::Vector3d(rot * d0), Eigen::Vector3d(-d0.x(), 0.6, -d0.z()).normalized(),
                                   Eigen::Vector3d(0.01, 0.0, -d0.z()).normalized()}) {
    const Eigen::Matrix3d f = framed.rotation_frame(6, d);
    EXPECT_LT((f.transpose() * f - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    EXPECT_EQ(f.col(2), d);
    EXPECT_NEAR(f.determinant(), 1.0, 1e-14);
  }

  // A bent state reached by translations only (no rotation unknowns, so the same for both):
  // internal forces in x, y, z equal, element residuals equal up to the frames.
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(plain.num_dofs());
  for (int n = 0; n < 10; ++n) delta(ShellModel::dof(n, 2)) = 0.02 * m.nodes[static_cast<std::size_t>(n)].x() * m.nodes[static_cast<std::size_t>(n)].x();
  plain.set_trial(delta, 1.0);
  framed.set_trial(delta, 1.0);
  const Eigen::VectorXd fp = plain.internal_forces(), ff = framed.internal_forces();
  EXPECT_GT(fp.norm(), 0.0);
  EXPECT_LT((ff - fp).norm(), 1e-12 * fp.norm());
  Eigen::VectorXd rp, rf;
  plain.evaluate_element(2, &rp, nullptr);
  framed.evaluate_element(2, &rf, nullptr);
  const int corner = 0, node = m.quads[2][corner];
  ASSERT_TRUE(framed.has_rotation_frame(node));
  EXPECT_LT((rf.segment<3>(3) - framed.rotation_frame(node, d0).transpose() * rp.segment<3>(3)).norm(), 1e-12 * rp.norm());
}

}  // namespace
}  // namespace spifit::model
