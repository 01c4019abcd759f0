// The one-point ShellQ4 (ShellOptions::hourglass_stiffness > 0): layers at the centre, an elastic
// stiffness on the strains' variation over the element.
#include "forward/element/director.hpp"
#include "forward/element/shell_q4.hpp"
#include "tests/support/shell_finite_differences.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cstdio>

namespace spifit::element {
namespace {

material::MaterialParams<double> aa3003(bool plastic = true) {  // card C.3 + C.4
  material::MaterialParams<double> p;
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;
  p.plastic = plastic;
  return p;
}

// A distorted, slightly warped quad with non-parallel directors (as shell_q4_test.cpp).
const NodeVectors kX = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(2.2, 0.1, 0.05), Eigen::Vector3d(2.0, 1.9, -0.04),
                        Eigen::Vector3d(-0.2, 1.7, 0.02)};
const NodeVectors kD = {Eigen::Vector3d(0.02, -0.01, 1.0).normalized(), Eigen::Vector3d(-0.03, 0.0, 1.0).normalized(),
                        Eigen::Vector3d(0.0, 0.04, 1.0).normalized(), Eigen::Vector3d(0.01, 0.02, 1.0).normalized()};
const NodeVectors kUp = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()};

ShellOptions one_point(double hourglass) {
  ShellOptions o;
  o.layer_tangents = false;
  o.hourglass_stiffness = hourglass;
  return o;
}

// Stretch s, a non-uniform bending b and a rigid rotation of the reference quad X with directors D.
void deform(const NodeVectors& X, const NodeVectors& D, double s, double b, const Eigen::Vector3d& rigid, NodeVectors* x, NodeVectors* d) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(rigid.norm(), rigid.norm() > 0 ? rigid.normalized() : Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector3d& p = X[i];
    const Eigen::Vector3d q(p.x() * (1.0 + s), p.y() * (1.0 + 0.3 * s) + 0.2 * s * p.x() * p.y(), p.z() + b * (p.x() * p.x() - 0.5 * p.y() * p.y()));
    (*x)[i] = R * q;
    (*d)[i] = R * rotate_by_vector(D[i], Eigen::Vector3d(b * p.y(), -2.0 * b * p.x(), 0.0));
  }
}

// Elastic energy of a fresh element at (x, d): its trial state committed (no thickness history).
double fresh_energy(const material::ReturnMapping<double, 3>& law, const ThicknessRule& rule, const ShellOptions& o, const NodeVectors& x,
                    const NodeVectors& d) {
  ShellQ4 el(kX, kD, 0.8, law, rule, o);
  Vec24 r;
  EXPECT_TRUE(el.compute(x, d, &r, nullptr).ok);
  el.commit();
  const ElementEnergy e = el.energy(x, d);
  return e.elastic + e.transverse_shear;
}

// Largest difference between the residual and the central differences of the energy over the
// 24 DOFs (rotations applied to the directors), relative to the residual's norm.
double gradient_error(const ShellOptions& o) {
  const material::ReturnMapping<double, 3> law(aa3003(false));
  const ThicknessRule rule = gauss_legendre_rule(5);
  NodeVectors x, d;
  deform(kX, kD, 0.01, 0.03, Eigen::Vector3d(0.3, -0.2, 0.5), &x, &d);
  ShellQ4 el(kX, kD, 0.8, law, rule, o);
  Vec24 r;
  EXPECT_TRUE(el.compute(x, d, &r, nullptr).ok);
  const double h = 1e-6;
  double err = 0.0;
  for (int j = 0; j < 24; ++j) {
    double e[2];
    for (int s = 0; s < 2; ++s) {
      NodeVectors xp = x, dp = d;
      test::perturb(j, s == 0 ? h : -h, &xp, &dp);
      e[s] = fresh_energy(law, rule, o, xp, dp);
    }
    err = std::max(err, std::abs((e[0] - e[1]) / (2.0 * h) - r(j)));
  }
  return err / r.norm();
}

TEST(ShellQ4OnePoint, ResidualIsTheGradientOfItsEnergyWithTheHourglassPart) {
  const double full = gradient_error(ShellOptions{});
  const double reduced = gradient_error(one_point(0.5));
  std::printf("relative gradient error: 2 x 2 points %.2e, one point %.2e\n", full, reduced);
  EXPECT_LT(full, 1e-6);
  EXPECT_LT(reduced, 1e-6);
}

TEST(ShellQ4OnePoint, UniformStrainOfARectangleGivesTheFullElementsForces) {
  // A rectangle stretched and bent uniformly: every 2 x 2 point has the centre's strains, so
  // the hourglass part is zero and the one point carries what the four did, plastic too.
  const NodeVectors X = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(2.0, 0.0, 0.0), Eigen::Vector3d(2.0, 1.5, 0.0),
                         Eigen::Vector3d(0.0, 1.5, 0.0)};
  const material::ReturnMapping<double, 3> law(aa3003());
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellOptions full;
  full.layer_tangents = false;
  ShellQ4 a(X, kUp, 1.0, law, rule, full), b(X, kUp, 1.0, law, rule, one_point(1.0));
  // Cylindrical bending about y with radius rho and a stretch along x.
  const double rho = 20.0, stretch = 1.04;
  NodeVectors x, d;
  for (std::size_t i = 0; i < 4; ++i) {
    const double phi = stretch * X[i].x() / rho;
    x[i] = Eigen::Vector3d(rho * std::sin(phi), X[i].y(), rho * (1.0 - std::cos(phi)));
    d[i] = Eigen::Vector3d(-std::sin(phi), 0.0, std::cos(phi));
  }
  Vec24 ra, rb;
  ASSERT_TRUE(a.compute(x, d, &ra, nullptr).ok);
  ASSERT_TRUE(b.compute(x, d, &rb, nullptr).ok);
  a.commit();
  b.commit();
  EXPECT_GT(b.section(0).layer_state(4).eqps, 0.01);  // plastic
  const double rel = (ra - rb).norm() / ra.norm();
  std::printf("one point against 2 x 2 points: relative difference %.2e, |r| %.3f\n", rel, ra.norm());
  EXPECT_LT(rel, 1e-10);
  EXPECT_EQ(b.points(), 1);
  EXPECT_EQ(a.points(), 4);
  EXPECT_NEAR(b.section(0).thickness(), a.section(0).thickness(), 1e-12);
}

// The stiffness at the reference state by central differences of the residual, its symmetric
// part's eigenvalues counted below 1e-9 of the largest: the modes without energy.
int zero_energy_modes(const ShellOptions& o) {
  const material::ReturnMapping<double, 3> law(aa3003(false));
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellQ4 el(kX, kD, 0.8, law, rule, o);
  const Mat24 k = test::fd_tangent(el, kX, kD, 1e-7);
  Eigen::SelfAdjointEigenSolver<Mat24> es(0.5 * (k + k.transpose()));
  const double top = es.eigenvalues().cwiseAbs().maxCoeff();
  int zeros = 0;
  for (int i = 0; i < 24; ++i) zeros += std::abs(es.eigenvalues()(i)) < 1e-9 * top;
  return zeros;
}

TEST(ShellQ4OnePoint, HourglassStiffnessLeavesOnlyTheRigidAndDrillingModes) {
  // 6 rigid-body modes and the 4 drilling rotations (no residual); the one-point element
  // without the hourglass part would add its membrane and bending hourglass modes.
  const int full = zero_energy_modes(ShellOptions{});
  const int reduced = zero_energy_modes(one_point(0.05));
  std::printf("zero-energy modes: 2 x 2 points %d, one point %d\n", full, reduced);
  EXPECT_EQ(full, 10);
  EXPECT_EQ(reduced, 10);
}

TEST(ShellQ4OnePoint, RigidMotionIsStressFree) {
  const material::ReturnMapping<double, 3> law(aa3003());
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellQ4 el(kX, kD, 0.8, law, rule, one_point(1.0));
  NodeVectors x, d, xs, ds;
  deform(kX, kD, 0.0, 0.0, Eigen::Vector3d(2.0, 1.0, -2.5), &x, &d);
  for (auto& xi : x) xi += Eigen::Vector3d(3.0, -7.0, 11.0);
  deform(kX, kD, 1e-3, 0.0, Eigen::Vector3d::Zero(), &xs, &ds);
  Vec24 r, rs;
  ASSERT_TRUE(el.compute(x, d, &r, nullptr).ok);
  ASSERT_TRUE(el.compute(xs, ds, &rs, nullptr).ok);
  EXPECT_LT(r.norm(), 1e-10 * rs.norm());
}

TEST(ShellQ4OnePoint, TangentMatchesFiniteDifferencesAfterPlasticPrestrainAndLargeRotation) {
  // The explicit scheme's stable step comes from this tangent's largest eigenvalue.
  const material::ReturnMapping<double, 3> law(aa3003());
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellOptions o = one_point(0.3);
  o.layer_tangents = true;
  ShellQ4 el(kX, kD, 1.2, law, rule, o);
  NodeVectors x, d;
  deform(kX, kD, 0.05, 0.05, Eigen::Vector3d::Zero(), &x, &d);
  Vec24 r;
  ASSERT_TRUE(el.compute(x, d, &r, nullptr).ok);
  el.commit();
  ASSERT_GT(el.section(0).layer_state(0).eqps, 0.01);
  deform(kX, kD, 0.08, 0.07, Eigen::Vector3d(0.9, -1.4, 0.6), &x, &d);
  Mat24 k;
  ASSERT_TRUE(el.compute(x, d, &r, &k).ok);
  const Mat24 kfd = test::fd_tangent(el, x, d, 1e-7);
  // On the rotations normal to the directors (the drilling rows hold the regularisation only).
  Mat24 P = Mat24::Identity();
  for (std::size_t i = 0; i < 4; ++i) P.block<3, 3>(6 * static_cast<int>(i) + 3, 6 * static_cast<int>(i) + 3) -= d[i] * d[i].transpose();
  const double err = (P * (k - kfd) * P).norm() / (P * k * P).norm();
  std::printf("one point, plastic and rotated: relative tangent error %.3e\n", err);
  EXPECT_LT(err, 1e-5);
}

}  // namespace
}  // namespace spifit::element
