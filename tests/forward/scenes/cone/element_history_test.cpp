// Element history (thesis §9.4): the nearest element, centre strains and curvatures in
// the initial polar frame for known homogeneous deformations, tensor rotation, von Mises, and
// the committed layer stresses of a real ShellModel under a prescribed homogeneous strain.
#include "forward/element/thickness_rule.hpp"
#include "forward/mesh/disc_mesh.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/scenes/cone/element_history.hpp"
#include "tests/support/cards.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace spifit::scene {
namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }

// A square of side a centred at radius rc, polar angle theta, its sides turned by `turn` from
// the radial direction; counter-clockwise seen from +z.
element::NodeVectors square(double rc, double theta, double a, double turn) {
  const Eigen::Vector3d c(rc * std::cos(theta), rc * std::sin(theta), 0.0);
  const Eigen::Vector3d u(std::cos(theta + turn), std::sin(theta + turn), 0.0), v(-u.y(), u.x(), 0.0);
  return {c - 0.5 * a * u - 0.5 * a * v, c + 0.5 * a * u - 0.5 * a * v, c + 0.5 * a * u + 0.5 * a * v, c - 0.5 * a * u + 0.5 * a * v};
}

element::NodeVectors same_at_nodes(const Eigen::Vector3d& v) { return {v, v, v, v}; }

TEST(ElementHistory, NearestElementByCentroidTiesToTheLowestIndex) {
  mesh::Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  m.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  EXPECT_EQ(nearest_element(m, std::hypot(1.6, 0.5), std::atan2(0.5, 1.6) * 180.0 / kPi), 1);
  EXPECT_EQ(nearest_element(m, std::hypot(0.2, 0.5), std::atan2(0.5, 0.2) * 180.0 / kPi), 0);
  EXPECT_EQ(nearest_element(m, std::hypot(1.0, 0.5), std::atan2(0.5, 1.0) * 180.0 / kPi), 0);  // equidistant
  EXPECT_EQ(nearest_element(mesh::Mesh{}, 1.0, 0.0), -1);
}

TEST(ElementHistory, HomogeneousStretchAndShearInThePolarFrame) {
  // F = Q (lr e_r e_r^T + lt e_t e_t^T + g e_r e_t^T): E_rr = (lr^2 - 1)/2, E_tt = (lt^2 + g^2 - 1)/2,
  // gamma_rt = lr g, whatever the rigid rotation Q and the element's orientation in the plane.
  const double theta = rad(30.0);
  const element::NodeVectors X = square(75.0, theta, 1.2, rad(17.0));
  const Eigen::Vector3d er(std::cos(theta), std::sin(theta), 0.0), et(-std::sin(theta), std::cos(theta), 0.0), ez = Eigen::Vector3d::UnitZ();
  const double lr = 2.3, lt = 1.03, g = 0.08;
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -1.0, 0.4).normalized()).toRotationMatrix();
  const Eigen::Matrix3d F = Q * (lr * er * er.transpose() + lt * et * et.transpose() + g * er * et.transpose() + ez * ez.transpose());
  const Eigen::Vector3d shift(3.0, -2.0, -17.0);
  element::NodeVectors x;
  for (std::size_t i = 0; i < 4; ++i) x[i] = F * X[i] + shift;
  const PolarStrains s = centre_polar_strains(X, same_at_nodes(ez), x, same_at_nodes(Eigen::Vector3d(Q * ez)));
  EXPECT_NEAR(s.membrane(0), 0.5 * (lr * lr - 1.0), 1e-12);
  EXPECT_NEAR(s.membrane(1), 0.5 * (lt * lt + g * g - 1.0), 1e-12);
  EXPECT_NEAR(s.membrane(2), lr * g, 1e-12);
  EXPECT_NEAR(s.stretch_r, lr, 1e-12);
  EXPECT_NEAR(s.stretch_theta, std::hypot(lt, g), 1e-12);
  EXPECT_NEAR(s.bending.norm(), 0.0, 1e-12);  // directors rotated rigidly: no curvature
}

TEST(ElementHistory, BendingFromTiltedDirectors) {
  // Flat element aligned with e_r, directors tilted along e_r in proportion to the radial
  // offset: d_I = (z + k a_I e_r) / sqrt(1 + k^2 a_I^2), |a_I| = a / 2, so at the centre
  // d d / d r = k / sqrt(1 + k^2 a^2 / 4) e_r: K_rr = that, K_tt = K_rt = 0.
  const double theta = rad(22.5), a = 0.7, k = 0.2;
  const element::NodeVectors X = square(40.0, theta, a, 0.0);
  const Eigen::Vector3d er(std::cos(theta), std::sin(theta), 0.0), ez = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d c = 0.25 * (X[0] + X[1] + X[2] + X[3]);
  element::NodeVectors d;
  for (std::size_t i = 0; i < 4; ++i) d[i] = (ez + k * (X[i] - c).dot(er) * er).normalized();
  const PolarStrains s = centre_polar_strains(X, same_at_nodes(ez), X, d);
  EXPECT_NEAR(s.bending(0), k / std::sqrt(1.0 + k * k * a * a / 4.0), 1e-12);
  EXPECT_NEAR(s.bending(1), 0.0, 1e-12);
  EXPECT_NEAR(s.bending(2), 0.0, 1e-12);
  EXPECT_NEAR(s.membrane.norm(), 0.0, 1e-12);
}

TEST(ElementHistory, TensorRotationAndVonMises) {
  // Uniaxial 100 MPa along m1, frame turned by 30 deg: e_r = cos30 m1 + sin30 m2.
  const Eigen::Vector3d r = rotate_tensor_components({100.0, 0.0, 0.0}, std::cos(rad(30.0)), std::sin(rad(30.0)));
  EXPECT_NEAR(r(0), 75.0, 1e-12);
  EXPECT_NEAR(r(1), 25.0, 1e-12);
  EXPECT_NEAR(r(2), -43.30127018922193, 1e-12);
  EXPECT_NEAR(von_mises_plane_stress(r), 100.0, 1e-12);  // invariant
  EXPECT_NEAR(von_mises_plane_stress({0.0, 0.0, 50.0}), 50.0 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(von_mises_plane_stress({80.0, 80.0, 0.0}), 80.0, 1e-12);
}

// The body of the test below, for the model's material axes: the layer stresses are kept in each
// element's material frame, so the history must turn them with the element's own rolling
// direction (polar axes: the radial direction, 30 deg from x at the element used).
void check_layer_stresses_under_prescribed_strain(model::ShellModelOptions::MaterialAxes axes) {
  // A 90 deg pie (radius 10 mm, t = 1 mm, card C.3 + C.4) strained homogeneously: x = X +
  // (a X_x, 0, 0) with (1 + a)^2 = 1 + 2 eps, i.e. E_xx = eps, E_yy = 0 (elastic, eps = 1e-4).
  // Plane stress: S_xx = E eps / (1 - nu^2), S_yy = nu S_xx; in the polar frame at the element's
  // centroid angle: E_rr = eps cos^2, E_tt = eps sin^2, gamma_rt = -2 eps cos sin.
  mesh::DiscOptions o;
  o.radius = 10.0;
  o.angle_deg = 90.0;
  o.elements_per_45deg = 4;
  const mesh::Mesh m = mesh::disc_mesh(o);
  const auto card = test::card("aa3003o_c3c4");
  model::ShellModelOptions mo;
  mo.shell.thickness_points = 3;
  mo.material_axes = axes;
  model::ShellModel model(m, 1.0, card.params, mo);
  const double eps = 1e-4, a = std::sqrt(1.0 + 2.0 * eps) - 1.0;
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(model.num_dofs());
  for (int n = 0; n < model.num_nodes(); ++n) delta(model::ShellModel::dof(n, 0)) = a * m.nodes[static_cast<std::size_t>(n)].x();
  model.set_trial(delta, 1.0);
  model.accept_trial();
  Eigen::VectorXd re;
  for (int e = 0; e < model.num_elements(); ++e) ASSERT_TRUE(model.evaluate_element(e, &re, nullptr).ok);
  model.commit(1.0);

  const element::ThicknessRule rule = element::make_thickness_rule(element::ThicknessRuleKind::gauss, 3);
  const double E = card.params.E, nu = card.params.nu, sxx = E * eps / (1.0 - nu * nu), syy = nu * sxx;
  const int e = nearest_element(m, 7.0, 30.0);
  const Eigen::Vector3d cen = m.centroid(e);
  const double th = std::atan2(cen.y(), cen.x()), c = std::cos(th), s = std::sin(th);
  const ElementHistoryRow row = element_history_row(model, e, rule);
  EXPECT_NEAR(row.centre.membrane(0), eps * c * c, 1e-14);
  EXPECT_NEAR(row.centre.membrane(1), eps * s * s, 1e-14);
  EXPECT_NEAR(row.centre.membrane(2), -2.0 * eps * c * s, 1e-14);
  EXPECT_NEAR(row.thickness, 1.0 / std::sqrt(1.0 + 2.0 * eps), 1e-12);  // constant volume (thesis §9.2.2)
  ASSERT_EQ(row.layers.size(), 3u);
  for (const auto& l : row.layers) {
    // Log strain vs Green strain: relative O(eps).
    EXPECT_NEAR(l.stress(0), c * c * sxx + s * s * syy, 2e-4 * sxx);
    EXPECT_NEAR(l.stress(1), s * s * sxx + c * c * syy, 2e-4 * sxx);
    EXPECT_NEAR(l.stress(2), -c * s * sxx + c * s * syy, 2e-4 * sxx);
    EXPECT_NEAR(l.von_mises, std::sqrt(sxx * sxx - sxx * syy + syy * syy), 2e-4 * sxx);
    EXPECT_EQ(l.eqps, 0.0);
    EXPECT_NEAR((l.strain - row.centre.membrane).norm(), 0.0, 1e-15);  // no bending
  }
  EXPECT_NEAR(row.von_mises_mean, row.layers[1].von_mises, 1e-9 * sxx);
  const auto cols = element_history_columns(3);
  const auto vals = element_history_values(12.5, 0.25, row);
  ASSERT_EQ(cols.size(), vals.size());
  EXPECT_EQ(cols.size(), 12u + 3u * 9u);
  EXPECT_EQ(cols[5], "E_rr");
  EXPECT_EQ(vals[0], 12.5);
  EXPECT_EQ(vals[5], row.centre.membrane(0));
  EXPECT_EQ(cols.back(), "L3_eqps");
}

TEST(ElementHistory, LayerStressesOfAShellModelUnderPrescribedStrain) {
  check_layer_stresses_under_prescribed_strain(model::ShellModelOptions::MaterialAxes::fixed);
}

TEST(ElementHistory, LayerStressesWithPolarMaterialAxes) {
  check_layer_stresses_under_prescribed_strain(model::ShellModelOptions::MaterialAxes::polar);
}

}  // namespace
}  // namespace spifit::scene
