// The solid-shell (one element through the thickness, ANS + EAS, several points along it):
// homogeneous states against the one-point brick, the patch test, zero-energy modes, the exact
// tangent against central differences, and 3D pure bending of thin and thick strips against the
// exact solution.
#include "forward/element/brick8.hpp"
#include "forward/element/solid_shell8.hpp"

#include "tests/support/hex_elements.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <vector>

namespace spifit::element {
namespace {

using test::aa3003;
using test::aa3003_af;
using test::box;
using test::map;
using test::rotation;
using test::zero_eigenvalues;

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

material::MaterialParams<double> elastic(double nu) {
  material::MaterialParams<double> p;
  p.E = 70000.0;
  p.nu = nu;
  return p;
}

// A quadrilateral of a sheet extruded along its normal: distorted in the plane, its corner
// columns straight and normal to the sheet (what mesh::extrude_sheet makes of a flat sheet).
HexCorners distorted() {
  HexCorners X = box(2.0, 1.5, 0.3);
  const Vec3 shift[4] = {{0.0, 0.0, 0.0}, {0.2, -0.1, 0.0}, {-0.15, 0.2, 0.0}, {0.1, 0.15, 0.0}};
  for (std::size_t I = 0; I < 4; ++I) {
    X[I] += shift[I];
    X[I + 4] += shift[I];
  }
  return X;
}

ThicknessRule five() { return gauss_legendre_rule(5); }

// A homogeneous deformation gives every point the same strain: the nodal forces equal the
// one-point brick's (whose hourglass amplitudes vanish for linear fields), on a box and on a
// sheared parallelepiped, plastic, with global and turned material axes. (On a quadrilateral
// distorted in its plane, the element's own nodal forces differ from the brick's where the stress
// has transverse shear, the assumed shears being tied at xi = 0 or eta = 0; a patch of them
// still sums to the exact interior forces, below.)
TEST(SolidShell8, HomogeneousDeformationGivesTheBricksForces) {
  const SolidPoint::Law law(aa3003());
  HexCorners sheared = box(2.0, 1.5, 0.3);
  for (std::size_t I = 4; I < 8; ++I) sheared[I] += Vec3(0.12, -0.05, 0.0);
  Mat3 F;
  F << 1.2, 0.1, -0.05, 0.03, 0.9, 0.06, -0.02, 0.04, 0.85;
  for (const HexCorners& X : {box(2.0, 1.5, 0.3), sheared})
    for (const Mat3& axes : {Mat3(Mat3::Identity()), rotation()}) {
      SolidShell8 shell(X, axes, law, five());
      Brick8 brick(X, axes, law);
      HexVector fs, fb;
      const HexCorners x = map(X, rotation() * F, Vec3(0.3, -0.2, 1.0));
      ASSERT_TRUE(shell.evaluate(x, &fs, nullptr).ok);
      ASSERT_TRUE(brick.evaluate(x, &fb, nullptr).ok);
      ASSERT_GT(shell.point(0).trial().eqps, 0.05);
      EXPECT_LT((fs - fb).cwiseAbs().maxCoeff(), 1e-9 * fb.cwiseAbs().maxCoeff());
    }
}

// Large-strain patch test: a 2 x 2 patch of solid-shells (one through the thickness), rectangles
// or distorted in the plane (columns straight, as mesh::extrude_sheet makes them), whose nodes
// follow one homogeneous plastic deformation: the forces on the interior column equal those of the
// same patch of one-point bricks (exact for homogeneous states), so a constant stress is in
// equilibrium.
Eigen::Matrix<double, 6, 1> patch_column_forces(double distortion, bool shells) {
  const SolidPoint::Law law(aa3003());
  Vec3 nodes[18];
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) nodes[9 * k + 3 * j + i] = Vec3(i * (i == 2 ? 1.3 : 1.0), j * 0.8, k * 0.2);
  for (int k : {4, 13}) nodes[k] += distortion * Vec3(0.17, -0.11, 0.0);  // the interior column, moved in the plane
  Mat3 F;
  F << 1.3, 0.2, 0.05, -0.1, 0.85, 0.0, 0.04, 0.1, 0.92;
  F = rotation() * F;
  Eigen::Matrix<double, 6, 1> column = Eigen::Matrix<double, 6, 1>::Zero();
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int base = 3 * j + i;
      const int ids[8] = {base, base + 1, base + 4, base + 3, base + 9, base + 10, base + 13, base + 12};
      HexCorners X;
      for (int I = 0; I < 8; ++I) X[static_cast<std::size_t>(I)] = nodes[ids[I]];
      HexVector f;
      if (shells) {
        SolidShell8 shell(X, Mat3::Identity(), law, five());
        EXPECT_TRUE(shell.evaluate(map(X, F), &f, nullptr).ok);
      } else {
        Brick8 brick(X, Mat3::Identity(), law);
        EXPECT_TRUE(brick.evaluate(map(X, F), &f, nullptr).ok);
      }
      for (int I = 0; I < 8; ++I) {
        if (ids[I] == 4) column.head<3>() += f.segment<3>(3 * I);
        if (ids[I] == 13) column.tail<3>() += f.segment<3>(3 * I);
      }
    }
  return column;
}

TEST(SolidShell8, PatchUnderAHomogeneousDeformationMatchesTheBricks) {
  for (double s : {0.0, 0.5, 1.0}) {
    const Eigen::Matrix<double, 6, 1> shells = patch_column_forces(s, true), bricks = patch_column_forces(s, false);
    const double err = (shells - bricks).cwiseAbs().maxCoeff() / bricks.cwiseAbs().maxCoeff();
    std::printf("solid-shell patch, homogeneous deformation, interior column moved by %g x (0.17, -0.11): force error %.2e of the bricks'\n", s, err);
    EXPECT_LT(err, 1e-12);
  }
}

// Full in-plane integration: only the six rigid-body modes are free of energy.
TEST(SolidShell8, OnlyRigidBodyModesAreFreeOfEnergy) {
  const SolidPoint::Law law(aa3003());
  for (const HexCorners& X : {box(2.0, 1.5, 0.3), distorted()}) {
    SolidShell8 shell(X, rotation(), law, five());
    HexVector f;
    HexMatrix K;
    ASSERT_TRUE(shell.evaluate(X, &f, &K).ok);
    EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_EQ(zero_eigenvalues(K), 6);
  }
}

// The condensed tangent against central differences of the forces, at a rotated, distorted,
// plastically loaded state reached from a committed plastic state, with the isotropic card C.3 +
// C.4 (a symmetric tangent) and with card C.7's back-stress (not symmetric).
TEST(SolidShell8, TangentMatchesCentralDifferences) {
  for (const bool kinematic : {false, true}) {
  const SolidPoint::Law law(kinematic ? aa3003_af() : aa3003());
  const HexCorners X = distorted();
  for (const Mat3& axes : {Mat3(Mat3::Identity()), rotation()}) {
    SolidShell8 shell(X, axes, law, five());
    Mat3 F;
    F << 1.15, 0.1, -0.05, 0.03, 0.92, 0.06, -0.02, 0.04, 0.9;
    HexCorners x = map(X, rotation() * F);
    x[2] += Vec3(0.05, 0.02, -0.03);
    x[4] += Vec3(-0.02, 0.04, 0.03);
    x[6] += Vec3(0.0, 0.0, 0.02);
    HexCorners x_half;
    for (std::size_t I = 0; I < 8; ++I) x_half[I] = 0.5 * (X[I] + x[I]);
    ASSERT_TRUE(shell.evaluate(x_half, nullptr, nullptr).ok);
    shell.commit();
    HexVector f;
    HexMatrix K;
    ASSERT_TRUE(shell.evaluate(x, &f, &K).ok);
    double eqps = 0.0;
    for (int p = 0; p < shell.num_points(); ++p) eqps = std::max(eqps, shell.point(p).trial().eqps);
    ASSERT_GT(eqps, 0.01);
    ASSERT_GT(shell.enhanced().cwiseAbs().maxCoeff() + 1.0, 1.0);
    const double h = 1e-7;
    double worst = 0.0;
    for (int j = 0; j < 24; ++j) {
      HexCorners xp = x, xm = x;
      xp[static_cast<std::size_t>(j / 3)](j % 3) += h;
      xm[static_cast<std::size_t>(j / 3)](j % 3) -= h;
      HexVector fp, fm;
      ASSERT_TRUE(shell.evaluate(xp, &fp, nullptr).ok);
      ASSERT_TRUE(shell.evaluate(xm, &fm, nullptr).ok);
      worst = std::max(worst, ((fp - fm) / (2.0 * h) - K.col(j)).cwiseAbs().maxCoeff());
    }
    std::printf("solid-shell tangent against central differences (%s): %.1e of the largest entry\n",
                kinematic ? "Armstrong-Frederick" : "isotropic", worst / K.cwiseAbs().maxCoeff());
    EXPECT_LT(worst, 1e-6 * K.cwiseAbs().maxCoeff());
    const double asymmetry = (K - K.transpose()).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
    if (kinematic) EXPECT_GT(asymmetry, 1e-6);
    else EXPECT_LT(asymmetry, 1e-9);
  }
  }
}

// A residual alone skips the tangent's block in the corners, not the blocks in the enhanced
// parameters the condensation needs: its forces, enhanced parameters and point states are those
// of the evaluation with the tangent, bit for bit, so an iterate's residual does not depend on
// whether its tangent was asked for.
TEST(SolidShell8, ResidualAloneEqualsTheResidualWithTheTangent) {
  const SolidPoint::Law law(aa3003());
  const HexCorners X = distorted();
  SolidShell8 with(X, rotation(), law, five()), alone(X, rotation(), law, five());
  Mat3 F;
  F << 1.12, 0.08, -0.04, 0.02, 0.94, 0.05, -0.03, 0.03, 0.91;
  for (const double s : {0.5, 1.0}) {
    HexCorners x;
    const HexCorners y = map(X, rotation() * F);
    for (std::size_t I = 0; I < 8; ++I) x[I] = X[I] + s * (y[I] - X[I]) + Vec3(0.0, 0.0, 0.01 * s * static_cast<double>(I % 3));
    HexVector f_with, f_alone;
    HexMatrix K;
    ASSERT_TRUE(with.evaluate(x, &f_with, &K).ok);
    ASSERT_TRUE(alone.evaluate(x, &f_alone, nullptr).ok);
    EXPECT_EQ(f_with, f_alone);
    EXPECT_EQ(with.enhanced(), alone.enhanced());
    with.commit();
    alone.commit();
    EXPECT_EQ(with.enhanced(), alone.enhanced());
    for (int p = 0; p < with.num_points(); ++p) EXPECT_EQ(with.point(p).committed().stress, alone.point(p).committed().stress);
  }
  double eqps = 0.0;
  for (int p = 0; p < with.num_points(); ++p) eqps = std::max(eqps, with.point(p).committed().eqps);
  EXPECT_GT(eqps, 0.01);
}

// 3D pure bending about y, curvature k: u = (k x z, -nu k y z, -k (x^2 + nu (z^2 - y^2)) / 2),
// sigma_xx = E k z alone. A strip of 10 x 1 solid-shells, the root held at the exact values, the
// tip loaded by the consistent nodal forces of sigma_xx, linearised at the reference state
// (k small): the largest nodal error over the tip deflection k L^2 / 2.
double bending_error(double nu, double h) {
  const double L = 10.0, b = 1.0, k = 1e-6, E = 70000.0;
  const int nx = 10, n = 4 * (nx + 1);
  std::vector<Vec3> nodes;
  for (int kz = 0; kz < 2; ++kz)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i <= nx; ++i) nodes.emplace_back(L * i / nx, -0.5 * b + b * j, -0.5 * h + h * kz);
  auto id = [&](int i, int j, int kz) { return i + (nx + 1) * (j + 2 * kz); };
  const SolidPoint::Law law(elastic(nu));
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < nx; ++i) {
    const int ids[8] = {id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0), id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1)};
    HexCorners X;
    for (int I = 0; I < 8; ++I) X[static_cast<std::size_t>(I)] = nodes[static_cast<std::size_t>(ids[I])];
    SolidShell8 shell(X, Mat3::Identity(), law, gauss_legendre_rule(3));
    HexMatrix Ke;
    if (!shell.evaluate(X, nullptr, &Ke).ok) return 1.0;
    for (int I = 0; I < 8; ++I)
      for (int J = 0; J < 8; ++J) K.block<3, 3>(3 * ids[I], 3 * ids[J]) += Ke.block<3, 3>(3 * I, 3 * J);
  }
  const auto exact = [&](const Vec3& x) {
    return Vec3(k * x.x() * x.z(), -nu * k * x.y() * x.z(), -0.5 * k * (x.x() * x.x() + nu * (x.z() * x.z() - x.y() * x.y())));
  };
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
  std::vector<int> free, fixed;
  for (int a = 0; a < n; ++a) {
    const Vec3& x = nodes[static_cast<std::size_t>(a)];
    if (x.x() == L) f(3 * a) = (x.z() > 0 ? 1.0 : -1.0) * E * k * b * h * h / 24.0;
    for (int c = 0; c < 3; ++c) (x.x() == 0.0 ? fixed : free).push_back(3 * a + c);
  }
  Eigen::VectorXd up(static_cast<Eigen::Index>(fixed.size()));
  for (std::size_t p = 0; p < fixed.size(); ++p) up(static_cast<Eigen::Index>(p)) = exact(nodes[static_cast<std::size_t>(fixed[p] / 3)])(fixed[p] % 3);
  const Eigen::MatrixXd Kff = K(free, free), Kfp = K(free, fixed);
  const Eigen::VectorXd uf = Kff.ldlt().solve(f(free) - Kfp * up);
  double err = 0.0;
  for (std::size_t i = 0; i < free.size(); ++i)
    err = std::max(err, std::abs(uf(static_cast<Eigen::Index>(i)) - exact(nodes[static_cast<std::size_t>(free[i] / 3)])(free[i] % 3)));
  return err / (0.5 * k * L * L);
}

// Exact up to round-off, which grows with the condition number of the strip's stiffness: the
// thickness stiffness of an element over the strip's bending stiffness, ~ L_e L^3 / h^4, times the
// bulk over the shear modulus, ~ 1 / (1 - 2 nu). No shear, thickness or volumetric locking.
TEST(SolidShell8, PureBendingOfThinAndThickStripsIsExact) {
  for (double h : {1.0, 0.1, 0.01})
    for (double nu : {0.0, 0.3, 0.4999}) {
      const double err = bending_error(nu, h);
      const double roundoff = 10.0 * 2.2e-16 * 1.0 * 1000.0 / std::pow(h, 4) / (1.0 - 2.0 * nu);
      std::printf("solid-shell pure bending, 10 x 1 elements, L/h = %g, nu = %g: largest nodal error / tip deflection %.1e (round-off bound %.1e)\n",
                  10.0 / h, nu, err, roundoff);
      if (roundoff < 1e-2) {
        EXPECT_LT(err, roundoff);
      }
    }
}

TEST(SolidShell8, RejectsAnInvertedElementAndBadAxes) {
  const SolidPoint::Law law(aa3003());
  const HexCorners X = box(1.0, 1.0, 0.2);
  SolidShell8 shell(X, Mat3::Identity(), law, five());
  const PointStatus s = shell.evaluate(map(X, Vec3(1.0, 1.0, -0.5).asDiagonal().toDenseMatrix()), nullptr, nullptr);
  EXPECT_FALSE(s.ok);
  EXPECT_LT(s.suggested_scale, 1.0);
  EXPECT_THROW(SolidShell8(X, 2.0 * Mat3::Identity(), law, five()), std::invalid_argument);
  HexCorners inverted = X;
  std::swap(inverted[0], inverted[4]);
  EXPECT_THROW(SolidShell8(inverted, Mat3::Identity(), law, five()), std::invalid_argument);
}

}  // namespace
}  // namespace spifit::element
