// The FE model over an element family other than the shell: a linear-elastic 8-node hexahedron
// (2 x 2 x 2 Gauss points, small strain: element::hex_full_stiffness) as a family written here, on solid sheets extruded from the
// quadrilateral generators. Three DOFs per node, Newton, reactions, energies, VTU, cyclic ties
// and hanging nodes; each against a homogeneous field the element reproduces exactly.
#include "forward/element/hex8_stiffness.hpp"
#include "forward/mesh/disc_mesh.hpp"
#include "forward/mesh/extruded_sheet.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/cyclic_symmetry.hpp"
#include "forward/model/fe_model.hpp"
#include "forward/model/hanging_nodes.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/model/model_vtu.hpp"
#include "forward/solver/newton_solver.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>

namespace spifit::model {
namespace {

using Mat24 = element::HexMatrix;
using Vec24 = element::HexVector;

class LinearHexFamily final : public ElementFamily {
 public:
  LinearHexFamily(const mesh::Mesh& mesh, double E, double nu) : mesh_(&mesh) {
    for (const mesh::Hex& h : mesh.hexes) {
      element::HexCorners X;
      for (std::size_t i = 0; i < 8; ++i) X[i] = mesh.nodes[static_cast<std::size_t>(h[i])];
      k_.push_back(element::hex_full_stiffness(X, element::isotropic_elasticity(E, nu)));
    }
  }
  std::string name() const override { return "linear_hex"; }
  int dofs_per_node() const override { return 3; }
  int num_elements() const override { return static_cast<int>(k_.size()); }
  std::vector<int> element_nodes(int e) const override { return {mesh_->hexes[static_cast<std::size_t>(e)].begin(), mesh_->hexes[static_cast<std::size_t>(e)].end()}; }
  solver::ElementEvaluation evaluate(int e, const ElementInputs& in, Eigen::VectorXd* re, Eigen::MatrixXd* ke) override {
    const Vec24 u = displacements(e, in.x);
    *re = k_[static_cast<std::size_t>(e)] * u;
    if (ke) *ke = k_[static_cast<std::size_t>(e)];
    return {};
  }
  void commit() override {}
  void revert() override {}
  double element_thickness(int e) const override {
    const mesh::Hex& h = mesh_->hexes[static_cast<std::size_t>(e)];
    return mesh_->nodes[static_cast<std::size_t>(h[4])].z() - mesh_->nodes[static_cast<std::size_t>(h[0])].z();
  }
  const std::vector<std::string>& warnings() const override { return warnings_; }
  void add_energies(const FeModel& model, ModelEnergies* energies) const override {
    for (int e = 0; e < num_elements(); ++e) {
      const Vec24 u = displacements(e, model.positions());
      energies->elastic += 0.5 * u.dot(k_[static_cast<std::size_t>(e)] * u);
    }
  }
  void add_vtu_data(const FeModel&, mesh::VtuFrame* frame) const override {
    frame->cell_data.push_back({"layer_height", 1, {}});
    for (int e = 0; e < num_elements(); ++e) frame->cell_data.back().values.push_back(element_thickness(e));
  }
  void save_state(io::BinaryWriter&) const override {}
  void load_state(io::BinaryReader&) override {}

 private:
  const mesh::Mesh* mesh_;
  std::vector<Mat24> k_;
  std::vector<std::string> warnings_;
  Vec24 displacements(int e, const std::vector<Eigen::Vector3d>& x) const {
    Vec24 u;
    const mesh::Hex& h = mesh_->hexes[static_cast<std::size_t>(e)];
    for (int i = 0; i < 8; ++i)
      u.segment<3>(3 * i) = x[static_cast<std::size_t>(h[static_cast<std::size_t>(i)])] - mesh_->nodes[static_cast<std::size_t>(h[static_cast<std::size_t>(i)])];
    return u;
  }
};

constexpr double kE = 70000.0, kNu = 0.33;

solver::NewtonOptions linear_options() {
  solver::NewtonOptions o;
  o.linear = true;
  o.initial_increment = o.max_increment = 1.0;
  return o;
}

TEST(FeModel, ThreeDofsPerNodeOfASolidFamily) {
  const mesh::Mesh mid = mesh::square_sheet({4.0, 2.0, 2, 2, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 1.0, 2);
  FeModel model(solid, std::make_unique<LinearHexFamily>(solid, kE, kNu));
  EXPECT_EQ(model.num_dofs(), 3 * solid.num_nodes());
  EXPECT_EQ(model.node_dofs(5), 3);
  EXPECT_EQ(model.node_dof(5, 2), 17);
  EXPECT_EQ(model.element_dofs()[0].size(), 24u);
  EXPECT_EQ(model.describe_dof(17).substr(0, 7), "node 5 ");
  EXPECT_NE(model.describe_dof(17).find("displacement z"), std::string::npos) << model.describe_dof(17);
  solver::DofConstraints c(model.num_dofs());
  try {
    model.use_nodal_rotation_frames(&c);
    ADD_FAILURE() << "rotation frames on nodes without rotations";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("linear_hex elements has no rotations"), std::string::npos) << e.what();
  }
}

// A 4 x 2 x 1 mm block pulled by 0.004 mm along x, sliding on its x = -2, y = -1 and z = -0.5
// faces: uniaxial stress, eps_xx = 1e-3, eps_yy = eps_zz = -nu eps_xx everywhere.
TEST(FeModel, SolidBlockUnderUniaxialStressIsExact) {
  const mesh::Mesh mid = mesh::square_sheet({4.0, 2.0, 2, 2, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 1.0, 2);
  FeModel model(solid, std::make_unique<LinearHexFamily>(solid, kE, kNu));
  solver::DofConstraints c(model.num_dofs());
  const double stretch = 0.004, eps = stretch / 4.0;
  for (int n : solid.node_sets.at("edge_xmin")) c.prescribe(model.node_dof(n, 0));
  for (int n : solid.node_sets.at("edge_xmax")) c.prescribe(model.node_dof(n, 0), stretch);
  for (int n : solid.node_sets.at("edge_ymin")) c.prescribe(model.node_dof(n, 1));
  for (int n : solid.node_sets.at("bottom")) c.prescribe(model.node_dof(n, 2));
  c.finalize();
  solver::NewtonSolver s(model, c, linear_options());
  ASSERT_TRUE(s.solve().converged);
  double err = 0.0;
  for (int n = 0; n < solid.num_nodes(); ++n) {
    const Eigen::Vector3d X = solid.nodes[static_cast<std::size_t>(n)];
    const Eigen::Vector3d exact(eps * (X.x() + 2.0), -kNu * eps * (X.y() + 1.0), -kNu * eps * (X.z() + 0.5));
    err = std::max(err, (model.displacement(n) - exact).norm());
  }
  EXPECT_LT(err, 1e-15 + 1e-12 * stretch);
  // The reaction on the pulled face carries sigma A = E eps (2 x 1 mm^2); the energy is F u / 2.
  const Eigen::VectorXd f = model.internal_forces();
  double pull = 0.0;
  for (int n : solid.node_sets.at("edge_xmax")) pull += f(model.node_dof(n, 0));
  EXPECT_NEAR(pull, kE * eps * 2.0, 1e-9 * kE * eps * 2.0);
  EXPECT_NEAR(energy_account(model).elastic, 0.5 * pull * stretch, 1e-9 * pull * stretch);
  const mesh::VtuFrame frame = vtu_frame(model);
  ASSERT_EQ(frame.point_data.size(), 1u);
  EXPECT_EQ(frame.point_data[0].name, "displacement");
  ASSERT_EQ(frame.cell_data.size(), 1u);
  EXPECT_EQ(frame.cell_data[0].values.size(), 8u);
  EXPECT_NE(mesh::vtu_text(solid, frame).find(" 12 12 12 12 12 12 12 12\n"), std::string::npos);
}

// A linear displacement field prescribed on the sides of a solid sheet with hanging nodes at
// every level: the hanging nodes follow their edges (translations only; a solid has no
// rotations to tie), and the field is reproduced exactly inside.
TEST(FeModel, HangingNodesOfASolidSheetFollowALinearField) {
  mesh::SquareSheetOptions o{16.0, 16.0, 8, 8, false, 1.0, 1.0, 1, {}};
  o.keep_fine = [](const Eigen::Vector2d& lo, const Eigen::Vector2d&) { return lo.x() < 0.0; };
  const mesh::Mesh mid = mesh::square_sheet(o);
  ASSERT_FALSE(mid.constrained_nodes.empty());
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 1.0, 2);
  FeModel model(solid, std::make_unique<LinearHexFamily>(solid, kE, kNu));
  Eigen::Matrix3d G;
  G << 1e-3, 2e-4, 0.0, -3e-4, 5e-4, 1e-4, 2e-4, 0.0, -4e-4;
  solver::DofConstraints c(model.num_dofs());
  tie_hanging_translations(model, &c);
  EXPECT_EQ(tie_hanging_rotations(model, &c), 0);
  for (const char* side : {"boundary", "bottom", "top"})
    for (int n : solid.node_sets.at(side)) {
      if (c.tied(model.node_dof(n, 0)) || c.prescribed(model.node_dof(n, 0))) continue;
      const Eigen::Vector3d u = G * solid.nodes[static_cast<std::size_t>(n)];
      for (int k = 0; k < 3; ++k) c.prescribe(model.node_dof(n, k), u(k));
    }
  c.finalize();
  solver::NewtonSolver s(model, c, linear_options());
  ASSERT_TRUE(s.solve().converged);
  double err = 0.0;
  for (int n = 0; n < solid.num_nodes(); ++n) err = std::max(err, (model.displacement(n) - G * solid.nodes[static_cast<std::size_t>(n)]).norm());
  EXPECT_LT(err, 1e-13);
  std::printf("solid sheet with %zu hanging nodes: largest error against the linear field %.2e mm\n", solid.constrained_nodes.size(), err);
}

// A 90 deg solid pie with cyclic ties on its edges, rim pushed out by 1 %, bottom held in z:
// the equibiaxial plane-stress expansion u = 0.01 (x, y), u_z = -2 nu / (1 - nu) 0.01 (z + t/2).
TEST(FeModel, CyclicTiesOfASolidPieReproduceTheDiscExpansion) {
  mesh::DiscOptions o;
  o.radius = 10.0;
  o.angle_deg = 90.0;
  o.elements_per_45deg = 4;
  const mesh::Mesh mid = mesh::disc_mesh(o);
  const double t = 1.0, eps = 0.01;
  const mesh::Mesh solid = mesh::extrude_sheet(mid, t, 2);
  FeModel model(solid, std::make_unique<LinearHexFamily>(solid, kE, kNu));
  solver::DofConstraints c(model.num_dofs());
  tie_cyclic_edges(model, "edge_theta0", "edge_theta1", 90.0, &c);
  for (int n : solid.node_sets.at("rim")) {
    if (c.tied(model.node_dof(n, 0))) continue;  // on the second edge: follows its partner
    const Eigen::Vector3d& p = solid.nodes[static_cast<std::size_t>(n)];
    c.prescribe(model.node_dof(n, 0), eps * p.x());
    c.prescribe(model.node_dof(n, 1), eps * p.y());
  }
  for (int n : solid.node_sets.at("bottom"))
    if (!c.tied(model.node_dof(n, 2))) c.prescribe(model.node_dof(n, 2));
  c.finalize();
  solver::NewtonSolver s(model, c, linear_options());
  ASSERT_TRUE(s.solve().converged);
  const double ezz = -2.0 * kNu / (1.0 - kNu) * eps;
  double err = 0.0;
  for (int n = 0; n < solid.num_nodes(); ++n) {
    const Eigen::Vector3d& p = solid.nodes[static_cast<std::size_t>(n)];
    err = std::max(err, (model.displacement(n) - Eigen::Vector3d(eps * p.x(), eps * p.y(), ezz * (p.z() + 0.5 * t))).norm());
  }
  EXPECT_LT(err, 1e-13);
}

}  // namespace
}  // namespace spifit::model
