#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/element/director.hpp"
#include "forward/element/shell_q4.hpp"
#include "tests/support/shell_finite_differences.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace spifit::element {
namespace {

material::MaterialParams<double> aa3003() {  // card C.3 + C.4
  material::MaterialParams<double> p;
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;
  return p;
}

struct Fixture {
  material::ReturnMapping<double, 3> law;
  ThicknessRule rule;
  ShellOptions options;
  NodeVectors X, D;
  explicit Fixture(const material::MaterialParams<double>& p, int layers = 5) : law(p), rule(gauss_legendre_rule(layers)) {
    // A distorted, slightly warped quad with non-parallel directors.
    X = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(2.2, 0.1, 0.05), Eigen::Vector3d(2.0, 1.9, -0.04),
         Eigen::Vector3d(-0.2, 1.7, 0.02)};
    D = {Eigen::Vector3d(0.02, -0.01, 1.0).normalized(), Eigen::Vector3d(-0.03, 0.0, 1.0).normalized(),
         Eigen::Vector3d(0.0, 0.04, 1.0).normalized(), Eigen::Vector3d(0.01, 0.02, 1.0).normalized()};
  }
};

// Moves the nodes: stretch (membrane strain ~ s), bending (curvature ~ b) and a rigid rotation.
void deform(const Fixture& f, double s, double b, const Eigen::Vector3d& rigid, NodeVectors* x, NodeVectors* d) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(rigid.norm(), rigid.norm() > 0 ? rigid.normalized() : Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& p = f.X[static_cast<std::size_t>(i)];
    Eigen::Vector3d q(p.x() * (1.0 + s), p.y() * (1.0 + 0.3 * s) + 0.2 * s * p.x(), p.z() + b * (p.x() * p.x() - 0.5 * p.y() * p.y()));
    (*x)[static_cast<std::size_t>(i)] = R * q;
    const Eigen::Vector3d tilt(-2.0 * b * p.x(), b * p.y(), 0.0);
    (*d)[static_cast<std::size_t>(i)] = R * rotate_by_vector(f.D[static_cast<std::size_t>(i)], Eigen::Vector3d(tilt.y(), tilt.x(), 0.0));
  }
}

using test::fd_tangent;

double tangent_error(ShellQ4& el, const NodeVectors& x, const NodeVectors& d, double h) {
  Vec24 r;
  Mat24 k;
  EXPECT_TRUE(el.compute(x, d, &r, &k).ok);
  const Mat24 kfd = fd_tangent(el, x, d, h);
  // Compare on the rotations normal to the directors (drilling carries no residual: its rows
  // and columns hold the regularisation only).
  Mat24 P = Mat24::Identity();
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& di = d[static_cast<std::size_t>(i)];
    P.block<3, 3>(6 * i + 3, 6 * i + 3) -= di * di.transpose();
  }
  const Mat24 diff = P * (k - kfd) * P;
  return diff.norm() / (P * k * P).norm();
}

TEST(ShellQ4, TangentMatchesFiniteDifferencesElastic) {
  Fixture f(aa3003());
  f.law = material::ReturnMapping<double, 3>([] { auto p = aa3003(); p.plastic = false; return p; }());
  ShellQ4 el(f.X, f.D, 0.3, f.law, f.rule, f.options);
  NodeVectors x, d;
  deform(f, 0.01, 0.02, Eigen::Vector3d::Zero(), &x, &d);
  const double err = tangent_error(el, x, d, 1e-6);
  std::printf("elastic: relative tangent error %.3e\n", err);
  EXPECT_LT(err, 1e-5);
}

TEST(ShellQ4, TangentMatchesFiniteDifferencesPlasticAfterCommittedPrestrain) {
  Fixture f(aa3003());
  ShellQ4 el(f.X, f.D, 1.2, f.law, f.rule, f.options);
  NodeVectors x, d;
  deform(f, 0.05, 0.05, Eigen::Vector3d::Zero(), &x, &d);
  Vec24 r;
  ASSERT_TRUE(el.compute(x, d, &r, nullptr).ok);
  el.commit();
  EXPECT_GT(el.section(0).layer_state(0).eqps, 0.01);
  deform(f, 0.08, 0.06, Eigen::Vector3d::Zero(), &x, &d);
  const double err = tangent_error(el, x, d, 1e-7);
  std::printf("plastic: relative tangent error %.3e\n", err);
  EXPECT_LT(err, 1e-5);
}

TEST(ShellQ4, TangentMatchesFiniteDifferencesPerfectPlasticityBending) {
  material::MaterialParams<double> p;  // von Mises, sigma_y = 10, no hardening (limit-moment strip)
  p.E = 70000.0; p.nu = 0.3; p.hardening[material::SwiftHardening::K] = 10.0; p.hardening[material::SwiftHardening::n] = 0.0;
  Fixture f(p, 11);
  ShellQ4 el(f.X, f.D, 0.1, f.law, f.rule, f.options);
  NodeVectors x, d;
  deform(f, 0.0005, 0.02, Eigen::Vector3d(0.0, 0.7, 0.0), &x, &d);
  Vec24 r;
  ASSERT_TRUE(el.compute(x, d, &r, nullptr).ok);
  el.commit();
  deform(f, 0.0006, 0.025, Eigen::Vector3d(0.0, 0.75, 0.0), &x, &d);
  const double err = tangent_error(el, x, d, 1e-8);
  std::printf("perfect plasticity: relative tangent error %.3e\n", err);
  EXPECT_LT(err, 1e-5);
}

TEST(ShellQ4, TangentMatchesFiniteDifferencesLargeRotationAndStrain) {
  Fixture f(aa3003());
  ShellQ4 el(f.X, f.D, 1.2, f.law, f.rule, f.options);
  NodeVectors x, d;
  deform(f, 0.8, 0.1, Eigen::Vector3d(0.9, -1.4, 0.6), &x, &d);  // 80 % stretch, 1.8 rad rotation
  const double err = tangent_error(el, x, d, 1e-7);
  std::printf("large rotation: relative tangent error %.3e\n", err);
  EXPECT_LT(err, 1e-5);
}

TEST(ShellQ4, RigidBodyMotionIsStressFree) {
  Fixture f(aa3003());
  ShellQ4 el(f.X, f.D, 0.5, f.law, f.rule, f.options);
  NodeVectors x, d;
  deform(f, 0.0, 0.0, Eigen::Vector3d(2.0, 1.0, -2.5), &x, &d);
  for (auto& xi : x) xi += Eigen::Vector3d(3.0, -7.0, 11.0);
  Vec24 r;
  Mat24 k;
  ASSERT_TRUE(el.compute(x, d, &r, &k).ok);
  EXPECT_LT(r.norm(), 1e-9 * k.norm());
  // Six rigid modes, no spurious zero-energy mode: with drilling regularisation the 24x24
  // tangent has exactly 6 (near-)zero eigenvalues.
  Eigen::SelfAdjointEigenSolver<Mat24> es(0.5 * (k + k.transpose()));
  const double top = es.eigenvalues().cwiseAbs().maxCoeff();
  int zeros = 0;
  for (int i = 0; i < 24; ++i) zeros += std::abs(es.eigenvalues()(i)) < 1e-10 * top;
  EXPECT_EQ(zeros, 6);
}

}  // namespace
}  // namespace spifit::element
