// The solid families on the FE model (bricks in layers, solid-shells): a solid sheet pulled far
// into the plastic range along its rolling direction, checked against what uniaxial stress
// under Hill 1948 must give; checkpoint state, refusals, the tool on the top faces, and plastic
// bending against the limit moment.
#include "forward/io/binary_archive.hpp"
#include "forward/mesh/extruded_sheet.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/solid_family.hpp"
#include "forward/model/fe_model.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/mesh/vtu_writer.hpp"
#include "forward/model/tool_contact.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace spifit::model {
namespace {

material::MaterialParams<double> aa3003() {  // card C.3 + C.4 (Hill 1948, G + H = 2, + Swift)
  material::MaterialParams<double> p;
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;
  return p;
}

// Newton over the load factor in equal steps.
solver::NewtonSummary solve_in_steps(FeModel& model, const solver::DofConstraints& c, double step) {
  solver::NewtonOptions o;
  o.initial_increment = o.max_increment = step;
  solver::NewtonSolver s(model, c, o);
  return s.solve();
}

// A 4 x 2 x 1 mm block in 2 x 2 x 3 bricks, or 2 x 2 solid-shells with five points through
// the thickness, stretched by 25 % along x (the rolling direction) and free to contract:
// uniaxial stress. Every integration point then holds the same state, with
//  * T_yy = T_zz = 0 (free lateral faces),
//  * T_xx = the Swift stress at the equivalent plastic strain (sigma_eq = sigma_xx when G + H = 2),
//  * the plastic width-to-thickness strain ratio r0 = H / G,
//  * the pull force T_xx / lambda_x over the reference section.
void pull_bar(SolidElementKind kind) {
  const int layers = kind == SolidElementKind::brick ? 3 : 1;
  const mesh::Mesh mid = mesh::square_sheet({4.0, 2.0, 2, 2, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 1.0, layers);
  SolidOptions options;
  options.element = kind;
  options.layers = layers;
  auto family = std::make_unique<SolidFamily>(solid, aa3003(), options);
  const SolidFamily& solids = *family;
  FeModel model(solid, std::move(family));
  solver::DofConstraints c(model.num_dofs());
  const double stretch = 1.0;  // 25 % of 4 mm
  for (int n : solid.node_sets.at("edge_xmin")) c.prescribe(model.node_dof(n, 0));
  for (int n : solid.node_sets.at("edge_xmax")) c.prescribe(model.node_dof(n, 0), stretch);
  for (int n : solid.node_sets.at("edge_ymin")) c.prescribe(model.node_dof(n, 1));
  for (int n : solid.node_sets.at("bottom")) c.prescribe(model.node_dof(n, 2));
  c.finalize();
  const auto result = solve_in_steps(model, c, 0.05);
  ASSERT_TRUE(result.converged) << result.message;
  const material::ReturnMapping<double, 6> law(aa3003());
  const double lx = 1.25;
  // Every integration point: (element, point) -> its SolidPoint.
  std::vector<const element::SolidPoint*> points;
  for (int e = 0; e < solids.num_elements(); ++e) {
    if (kind == SolidElementKind::brick) points.push_back(&solids.brick(e).point());
    else
      for (int q = 0; q < solids.solid_shell(e).num_points(); ++q) points.push_back(&solids.solid_shell(e).point(q));
  }
  const auto& st = points.front()->committed();
  ASSERT_GT(st.eqps, 0.2);
  for (std::size_t q = 0; q < points.size(); ++q)
    EXPECT_LT((points[q]->committed().stress - st.stress).cwiseAbs().maxCoeff(), 1e-8 * st.stress(0)) << q;
  EXPECT_LT(std::abs(st.stress(1)) + std::abs(st.stress(2)) + st.stress.tail<3>().cwiseAbs().sum(), 1e-8 * st.stress(0));
  EXPECT_NEAR(st.stress(0), law.yield_stress(st.eqps), 1e-9 * st.stress(0));
  EXPECT_NEAR(st.plastic_strain(1) / st.plastic_strain(2), 0.807 / 1.193, 1e-9);
  EXPECT_NEAR(solids.element_thickness(0), 1.0 * std::exp(points.front()->log_strain()(2)), 1e-12);
  const Eigen::VectorXd f = model.internal_forces();
  double pull = 0.0;
  for (int n : solid.node_sets.at("edge_xmax")) pull += f(model.node_dof(n, 0));
  EXPECT_NEAR(pull, st.stress(0) / lx * 2.0 * 1.0, 1e-9 * pull);
  const ModelEnergies en = energy_account(model);
  EXPECT_NEAR(en.plastic, st.plastic_work * 8.0, 1e-9 * en.plastic);
  EXPECT_GT(en.elastic, 0.0);
  std::printf("uniaxial Hill bar, %s: %d increments, eqps %.4f, T_xx %.3f MPa, r0 %.6f\n", solids.name().c_str(),
              static_cast<int>(result.history.size()), st.eqps, st.stress(0), st.plastic_strain(1) / st.plastic_strain(2));
}

TEST(SolidFamily, SolidBarPulledAlongTheRollingDirectionIsUniaxialHill) {
  SCOPED_TRACE("bricks");
  pull_bar(SolidElementKind::brick);
}

TEST(SolidFamily, SolidShellBarPulledAlongTheRollingDirectionIsUniaxialHill) {
  SCOPED_TRACE("solid-shells");
  pull_bar(SolidElementKind::solid_shell);
}

// A family's committed state written and read back into a second family: every element's
// energies, stresses and thickness bit for bit, and the next evaluation's forces too (so the
// hidden state, hourglass forces or enhanced strains and their predictor, came along).
void checkpoint_round_trip(SolidElementKind kind, int layers) {
  const mesh::Mesh mid = mesh::square_sheet({2.0, 2.0, 2, 1, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 0.5, layers);
  SolidOptions options;
  options.element = kind;
  options.layers = layers;
  SolidFamily a(solid, aa3003(), options), b(solid, aa3003(), options);
  std::vector<Eigen::Vector3d> x = solid.nodes;
  for (auto& p : x) p += Eigen::Vector3d(0.2 * p.x() + 0.05 * p.y() * p.y(), -0.06 * p.y(), 0.03 * p.x() * p.z());
  const std::vector<Eigen::Vector3d> d;
  const std::vector<std::unique_ptr<ElementContribution>> none;
  const NodalRotationFrames frames;
  const ElementInputs in{x, d, solid.nodes, d, none, frames};
  Eigen::VectorXd r;
  for (int e = 0; e < a.num_elements(); ++e) ASSERT_TRUE(a.evaluate(e, in, &r, nullptr).ok);
  a.commit();
  io::BinaryWriter w("test", 1);
  a.save_state(w);
  const std::string bytes = w.finish();
  io::BinaryReader rd(bytes, "test", 1);
  b.load_state(rd);
  std::vector<Eigen::Vector3d> x2 = x;
  for (auto& p : x2) p += Eigen::Vector3d(0.01 * p.y(), 0.02 * p.x(), -0.01 * p.z());
  const ElementInputs next{x2, d, solid.nodes, d, none, frames};
  for (int e = 0; e < a.num_elements(); ++e) {
    const element::SolidElement &ea = a.element(e), &eb = b.element(e);
    EXPECT_GT(ea.max_eqps(), 0.0) << e;
    EXPECT_EQ(ea.max_eqps(), eb.max_eqps()) << e;
    EXPECT_EQ(ea.mean_stress(), eb.mean_stress()) << e;
    EXPECT_EQ(ea.elastic_energy(), eb.elastic_energy()) << e;
    EXPECT_EQ(ea.plastic_work(), eb.plastic_work()) << e;
    EXPECT_EQ(a.element_thickness(e), b.element_thickness(e)) << e;
    Eigen::VectorXd ra, rb;
    ASSERT_TRUE(a.evaluate(e, next, &ra, nullptr).ok);
    ASSERT_TRUE(b.evaluate(e, next, &rb, nullptr).ok);
    EXPECT_EQ(ra, rb) << e;
  }
}

TEST(SolidFamily, CheckpointStateRoundTripsBitForBit) {
  {
    SCOPED_TRACE("bricks, 2 layers");
    checkpoint_round_trip(SolidElementKind::brick, 2);
  }
  {
    SCOPED_TRACE("solid-shells");
    checkpoint_round_trip(SolidElementKind::solid_shell, 1);
  }
}

TEST(SolidFamily, RefusesWhatItCannotModel) {
  const mesh::Mesh mid = mesh::square_sheet({2.0, 2.0, 2, 2, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 0.5, 2);
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { SolidFamily(mid, aa3003(), {}); }).find("needs a mesh of hexahedra"), std::string::npos);
  SolidOptions zero;
  zero.layers = 0;
  EXPECT_NE(message([&] { SolidFamily(solid, aa3003(), zero); }).find("at least one layer, got 0"), std::string::npos);
  SolidOptions three;
  three.layers = 3;
  EXPECT_NE(message([&] { SolidFamily(solid, aa3003(), three); }).find("are not 3 equal layers"), std::string::npos);
  SolidOptions normal;
  normal.material_axis = Eigen::Vector3d::UnitZ();
  EXPECT_NE(message([&] { SolidFamily(solid, aa3003(), normal); }).find("rolling direction lies along the sheet normal"), std::string::npos);
  SolidOptions stacked;
  stacked.element = SolidElementKind::solid_shell;
  stacked.layers = 2;
  EXPECT_NE(message([&] { SolidFamily(solid, aa3003(), stacked); }).find("one element through the thickness, got 2 layers"), std::string::npos);
  SolidOptions two;
  two.layers = 2;
  FeModel model(solid, std::make_unique<SolidFamily>(solid, aa3003(), two));
  contact::ContactOptions phong;
  phong.surface = contact::ContactOptions::Surface::phong;
  EXPECT_NE(message([&] { attach_tool(model, 5.0, [](double) { return Eigen::Vector3d(0.0, 0.0, 6.0); }, phong); }).find("solid elements take \"flat\""),
            std::string::npos);
  mesh::Mesh bare = solid;
  bare.face_sets.clear();
  FeModel no_top(bare, std::make_unique<SolidFamily>(bare, aa3003(), two));
  EXPECT_NE(message([&] { attach_tool(no_top, 5.0, [](double) { return Eigen::Vector3d(0.0, 0.0, 6.0); }, {}); }).find("no face set 'top'"),
            std::string::npos);
}

// A 10 x 10 x 1 mm sheet of two brick layers, clamped on its four edges, pressed 0.4 mm by a
// 5 mm tool at its centre: the tool acts on the top faces only, and the clamps carry its force.
TEST(SolidFamily, ToolPressesTheTopFacesAndTheClampsCarryItsForce) {
  const mesh::Mesh mid = mesh::square_sheet({10.0, 10.0, 6, 6, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 1.0, 2);
  SolidOptions options;
  options.layers = 2;
  FeModel model(solid, std::make_unique<SolidFamily>(solid, aa3003(), options));
  const double R = 5.0, depth = 0.4;
  const ToolContact& tool = attach_tool(model, R, [=](double lambda) { return Eigen::Vector3d(0.0, 0.0, 0.5 + R - depth * lambda); }, {});
  solver::DofConstraints c(model.num_dofs());
  for (const char* edge : {"edge_xmin", "edge_xmax", "edge_ymin", "edge_ymax"})
    for (int n : solid.node_sets.at(edge))
      for (int k = 0; k < 3; ++k)
        if (!c.prescribed(model.node_dof(n, k))) c.prescribe(model.node_dof(n, k));
  c.finalize();
  const auto result = solve_in_steps(model, c, 0.1);
  ASSERT_TRUE(result.converged) << result.message;
  const Eigen::Vector3d f = tool.summary().force_on_sheet;
  ASSERT_LT(f.z(), 0.0);
  const Eigen::VectorXd fi = model.internal_forces();
  Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
  for (int n = 0; n < solid.num_nodes(); ++n)
    if (c.prescribed(model.node_dof(n, 0)))
      for (int k = 0; k < 3; ++k) reaction(k) += fi(model.node_dof(n, k));
  // The clamps' reactions (the residual at the supported DOFs) balance the tool's force.
  EXPECT_LT((reaction + f).norm(), 1e-8 * std::abs(f.z())) << reaction.transpose() << " | " << f.transpose();
  EXPECT_LT(std::abs(f.x()) + std::abs(f.y()), 1e-9 * std::abs(f.z()));  // symmetric
  // Pressure on the top layer only.
  std::vector<mesh::VtuField> cells;
  model.contributions().front()->add_cell_data(&cells);
  ASSERT_EQ(cells.size(), 1u);
  double top = 0.0, bottom = 0.0;
  for (int e = 0; e < model.num_elements(); ++e) (e < 36 ? bottom : top) += cells[0].values[static_cast<std::size_t>(e)];
  EXPECT_GT(top, 0.0);
  EXPECT_EQ(bottom, 0.0);
  EXPECT_GE(tool.surface_penetration(model), tool.summary().max_penetration);
  std::printf("brick sheet pressed %.1f mm: tool force %.2f N, %d increments\n", depth, -f.z(), static_cast<int>(result.history.size()));
}

// The tangent of a top-layer brick with the tool's contact on its face (penalty, friction while
// the tool slides) against central differences of its forces, at a stretched and bent state.
TEST(SolidFamily, TangentWithTheToolOnTheTopFaceMatchesCentralDifferences) {
  const mesh::Mesh mid = mesh::square_sheet({4.0, 4.0, 2, 2, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 1.0, 2);
  SolidOptions options;
  options.layers = 2;
  FeModel model(solid, std::make_unique<SolidFamily>(solid, aa3003(), options));
  contact::ContactOptions co;
  co.friction = 0.1;
  const double R = 5.0;
  attach_tool(model, R, [=](double lambda) { return Eigen::Vector3d(0.4 + 0.3 * lambda, 0.2, 0.5 + R - 0.05 - 0.05 * lambda); }, co);
  model.begin_increment(0.0, 1.0);
  SolidFamily bricks(solid, aa3003(), options);  // evaluated here, with the model's tool
  std::vector<Eigen::Vector3d> x = solid.nodes;
  for (auto& p : x) p += Eigen::Vector3d(0.03 * p.x() - 0.01 * p.y() * p.z(), 0.02 * p.y(), -0.04 * (4.0 - p.x() * p.x() - p.y() * p.y()) * 0.1);
  const std::vector<Eigen::Vector3d> none;
  const NodalRotationFrames frames;
  const int e = 7;  // top layer, the element under the tool (corner at the origin)
  auto forces = [&](const std::vector<Eigen::Vector3d>& xs, Eigen::MatrixXd* k) {
    const ElementInputs in{xs, none, solid.nodes, none, model.contributions(), frames};
    Eigen::VectorXd r;
    EXPECT_TRUE(bricks.evaluate(e, in, &r, k).ok);
    return r;
  };
  Eigen::MatrixXd K;
  const Eigen::VectorXd f = forces(x, &K);
  Eigen::VectorXd bare;
  {
    const std::vector<std::unique_ptr<ElementContribution>> no_tool;
    const ElementInputs in{x, none, solid.nodes, none, no_tool, frames};
    ASSERT_TRUE(bricks.evaluate(e, in, &bare, nullptr).ok);
  }
  ASSERT_GT((f - bare).norm(), 1.0) << "the tool must touch the element's top face";
  const std::vector<int> nodes = bricks.element_nodes(e);
  const double h = 1e-7;
  double worst = 0.0;
  for (int j = 0; j < 24; ++j) {
    std::vector<Eigen::Vector3d> xp = x, xm = x;
    xp[static_cast<std::size_t>(nodes[static_cast<std::size_t>(j / 3)])](j % 3) += h;
    xm[static_cast<std::size_t>(nodes[static_cast<std::size_t>(j / 3)])](j % 3) -= h;
    worst = std::max(worst, ((forces(xp, nullptr) - forces(xm, nullptr)) / (2.0 * h) - K.col(j)).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-6 * K.cwiseAbs().maxCoeff());
  std::printf("brick with the tool on its face: tangent error %.2e of its largest entry\n", worst / K.cwiseAbs().maxCoeff());
}

// A plane-strain strip (1 x 1 x 1 mm, four elements along, y held) of an elastic-perfectly
// plastic von Mises material bent to 17 times its yield curvature by turning one end face by
// 0.005 rad (u_x = -theta z; the chord's shortening, theta^2 / 6 = 4e-6, is 3 % of the yield
// strain). Fully plastic layers carry the limit moment M_p = (2 / sqrt 3) sigma_y b h^2 / 4 at
// their centre points, and the hourglass forces add to it:
//  * with the stabilisation scaled down to 1e-3, the centres alone: M_p within 0.5 % for an even
//    number of layers;
//  * with the brick's stabilisation, on the centre's tangent or held elastic: above M_p, falling
//    with more layers, and the elastic one above the one on the tangent (equal with one layer,
//    whose centre lies on the neutral axis and stays elastic).
// Printed: M / M_p per layer count (docs/design/numerics-solid.md, "Plastic bending").
double bent_strip_moment_ratio(int layers, const element::HourglassOptions& hourglass, const SolidOptions& base = {}) {
  material::MaterialParams<double> p;
  p.E = 70000.0; p.nu = 0.3; p.hardening[material::SwiftHardening::K] = 10.0; p.hardening[material::SwiftHardening::n] = 0.0;
  p.F = p.G = p.H = 1.0; p.L = p.M = p.N = 3.0;
  const mesh::Mesh mid = mesh::square_sheet({1.0, 1.0, 4, 1, false, 1.0, 1.0, 0, {}});
  const mesh::Mesh solid = mesh::extrude_sheet(mid, 1.0, layers);
  SolidOptions options = base;
  options.layers = layers;
  options.hourglass = hourglass;
  FeModel model(solid, std::make_unique<SolidFamily>(solid, p, options));
  solver::DofConstraints c(model.num_dofs());
  const double theta = 0.005;
  for (int n = 0; n < solid.num_nodes(); ++n) c.prescribe(model.node_dof(n, 1));
  for (int n : solid.node_sets.at("edge_xmin")) {
    c.prescribe(model.node_dof(n, 0));
    c.prescribe(model.node_dof(n, 2));
  }
  for (int n : solid.node_sets.at("edge_xmax")) c.prescribe(model.node_dof(n, 0), -theta * solid.nodes[static_cast<std::size_t>(n)].z());
  c.finalize();
  const auto result = solve_in_steps(model, c, 0.05);
  if (!result.converged) {
    ADD_FAILURE() << layers << " layers: " << result.message;
    return 0.0;
  }
  const Eigen::VectorXd f = model.internal_forces();
  double M = 0.0;
  for (int n : solid.node_sets.at("edge_xmax")) M -= f(model.node_dof(n, 0)) * solid.nodes[static_cast<std::size_t>(n)].z();
  return M / (2.0 / std::sqrt(3.0) * 10.0 / 4.0);
}

TEST(SolidFamily, PlasticBendingMomentApproachesTheLimitMomentWithLayers) {
  double previous_tangent = 0.0, previous_elastic = 0.0;
  for (int layers : {1, 2, 4, 8}) {
    const double tangent = bent_strip_moment_ratio(layers, {1.0, false});
    const double elastic = bent_strip_moment_ratio(layers, {1.0, true});
    std::printf("plastic bending, %d layer(s): M / M_p = %.4f (stabilisation on the tangent), %.4f (elastic)", layers, tangent, elastic);
    if (layers % 2 == 0) {
      const double centres = bent_strip_moment_ratio(layers, {1e-3, false});
      std::printf(", %.4f (centres alone)", centres);
      EXPECT_NEAR(centres, 1.0, 5e-3) << layers;
      EXPECT_GT(tangent, 1.0) << layers;
      EXPECT_GT(elastic, tangent) << layers;
    }
    std::printf("\n");
    EXPECT_GE(elastic, tangent) << layers;  // equal for one layer: its centre stays elastic
    if (previous_tangent > 0.0) {
      EXPECT_LT(tangent, previous_tangent) << layers;
      EXPECT_LT(elastic, previous_elastic) << layers;
    }
    previous_tangent = tangent;
    previous_elastic = elastic;
  }
}

// The same strip with one solid-shell through the thickness: no hourglass modes, a 3D law at each
// point, so the moment is what the thickness rule integrates of the fully plastic section (the
// shell's section gives the same numbers, element/thickness_rule.hpp): 0.9449 M_p with five
// Gauss points (the stress jumps at the mid-surface), M_p with the surface rule (Simpson on each
// half).
TEST(SolidFamily, SolidShellCarriesThePlasticMomentItsThicknessRuleIntegrates) {
  SolidOptions gauss, surface;
  gauss.element = surface.element = SolidElementKind::solid_shell;
  gauss.thickness_rule = element::gauss_legendre_rule(5);
  surface.thickness_rule = element::make_thickness_rule(element::ThicknessRuleKind::surface, 5);
  const double mg = bent_strip_moment_ratio(1, {}, gauss), ms = bent_strip_moment_ratio(1, {}, surface);
  std::printf("plastic bending, one solid-shell: M / M_p = %.4f (5 Gauss points), %.4f (5 surface points)\n", mg, ms);
  EXPECT_NEAR(mg, 0.9449, 5e-3);
  EXPECT_NEAR(ms, 1.0, 5e-3);
}

}  // namespace
}  // namespace spifit::model
