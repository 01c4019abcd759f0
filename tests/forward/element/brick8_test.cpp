#include "forward/element/brick8.hpp"

#include "tests/support/hex_elements.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace spifit::element {
namespace {

using test::aa3003;
using test::aa3003_af;
using test::box;
using test::map;
using test::rotation;

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

HexCorners distorted() {
  HexCorners X = box(2.0, 1.5, 0.6);
  X[1] += Vec3(0.2, -0.1, 0.05);
  X[2] += Vec3(-0.15, 0.2, 0.0);
  X[6] += Vec3(0.1, 0.05, -0.08);
  X[7] += Vec3(-0.1, 0.1, 0.07);
  return X;
}

// The uniaxial force on the x = a face of a box stretched homogeneously, against the 3D return
// mapping fed the same log strain: exact conversion from T to the first Piola-Kirchhoff stress.
TEST(Brick8, HomogeneousStretchGivesTheMaterialPointsStress) {
  const SolidPoint::Law law(aa3003());
  for (int turned = 0; turned < 2; ++turned) {
    SCOPED_TRACE(turned ? "material axes turned 90 degrees about z" : "material axes global");
    const Mat3 axes = turned ? Mat3(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())) : Mat3::Identity();
    const HexCorners X = box(2.0, 1.5, 0.6);
    Brick8 brick(X, axes, law);
    const double lx = 1.25, ly = 0.93, lz = 0.87;
    HexVector f;
    ASSERT_TRUE(brick.evaluate(map(X, Vec3(lx, ly, lz).asDiagonal().toDenseMatrix()), &f, nullptr).ok);
    // The same strain in the law's axes.
    material::MaterialState<double, 6> s0, s1;
    Voigt6 eps = Voigt6::Zero();
    eps(turned ? 1 : 0) = std::log(lx);
    eps(turned ? 0 : 1) = std::log(ly);
    eps(2) = std::log(lz);
    ASSERT_TRUE(law.integrate(s0, eps, s1, nullptr).ok());
    ASSERT_GT(s1.eqps, 0.0);
    const double Txx = s1.stress(turned ? 1 : 0);
    double fx = 0.0;  // nodes 1, 2, 5, 6 lie on x = 2
    for (int I : {1, 2, 5, 6}) fx += f(3 * I);
    EXPECT_NEAR(fx, Txx / lx * 1.5 * 0.6, 1e-11 * std::abs(Txx));
    double fy = 0.0;  // nodes 2, 3, 6, 7 lie on y = 1.5
    for (int I : {2, 3, 6, 7}) fy += f(3 * I + 1);
    EXPECT_NEAR(fy, s1.stress(turned ? 0 : 1) / ly * 2.0 * 0.6, 1e-11 * std::abs(Txx));
    EXPECT_NEAR(brick.hourglass_energy(), 0.0, 0.0);  // linear field: no hourglass amplitude
  }
}

// An undeformed element has no forces at all, however far from the origin and however turned its
// material axes: the strain and the hourglass amplitudes come from the displacements. (From the
// positions, round-off gave forces of 1.3e-9 N here and 2e-9 N of residual in an unloaded cone
// pie, which Newton's relative force test could not pass.)
TEST(Brick8, UndeformedElementAwayFromTheOriginHasNoForces) {
  const SolidPoint::Law law(aa3003());
  const HexCorners X = map(distorted(), rotation(), Vec3(83.7, -41.3, 12.9));
  Brick8 brick(X, rotation().transpose(), law);
  HexVector f;
  HexMatrix K;
  ASSERT_TRUE(brick.evaluate(X, &f, &K).ok);
  EXPECT_EQ(f.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(K.norm(), 0.0);
}

// A rigid motion of a deformed, plastically loaded element leaves its forces turned with it and
// its stress and hourglass energy unchanged (objectivity).
TEST(Brick8, RigidRotationTurnsTheForcesAndKeepsTheEnergy) {
  const SolidPoint::Law law(aa3003());
  const HexCorners X = distorted();
  Brick8 brick(X, Mat3::Identity(), law);
  Mat3 F;
  F << 1.15, 0.08, -0.03, 0.02, 0.95, 0.04, 0.01, -0.05, 0.9;
  HexCorners x = map(X, F);
  x[6] += Vec3(0.03, -0.02, 0.04);  // an hourglass component
  HexVector f1, f2;
  ASSERT_TRUE(brick.evaluate(x, &f1, nullptr).ok);
  const double w1 = brick.point().trial().stress.norm();
  brick.commit();
  const double e1 = brick.hourglass_energy();
  ASSERT_GT(e1, 0.0);
  const Mat3 R = rotation();
  ASSERT_TRUE(brick.evaluate(map(x, R, Vec3(3.0, -1.0, 2.0)), &f2, nullptr).ok);
  brick.commit();
  EXPECT_NEAR(brick.hourglass_energy(), e1, 1e-12 * e1);
  EXPECT_NEAR(brick.point().committed().stress.norm(), w1, 1e-11 * w1);
  for (int I = 0; I < 8; ++I)
    EXPECT_LT((f2.segment<3>(3 * I) - R * f1.segment<3>(3 * I)).norm(), 1e-10 * f1.norm()) << I;
}

// The exact tangent against central differences of the forces, at a rotated, distorted,
// plastically loaded state with hourglass amplitudes, reached from a committed plastic state,
// for global and turned material axes, with the isotropic card C.3 + C.4 (associated flow:
// symmetric) and with card C.7's back-stress (not symmetric).
TEST(Brick8, TangentMatchesCentralDifferences) {
  for (const bool kinematic : {false, true}) {
  const SolidPoint::Law law(kinematic ? aa3003_af() : aa3003());
  const HexCorners X = distorted();
  for (const Mat3& axes : {Mat3(Mat3::Identity()), rotation()}) {
    Brick8 brick(X, axes, law);
    Mat3 F;
    F << 1.2, 0.1, -0.05, 0.03, 0.9, 0.06, -0.02, 0.04, 0.85;
    HexCorners x = map(X, rotation() * F);
    x[2] += Vec3(0.05, 0.02, -0.03);
    x[4] += Vec3(-0.02, 0.04, 0.03);
    // A committed plastic state first: the increment to x then starts from hourglass forces and
    // a stabilisation built on the elastic-plastic tangent.
    HexCorners x_half;
    for (std::size_t I = 0; I < 8; ++I) x_half[I] = 0.5 * (X[I] + x[I]);
    ASSERT_TRUE(brick.evaluate(x_half, nullptr, nullptr).ok);
    ASSERT_GT(brick.point().trial().eqps, 0.0);
    brick.commit();
    ASSERT_FALSE(brick.point().consistent_tangent() == law.elastic_matrix());
    HexVector f;
    HexMatrix K;
    ASSERT_TRUE(brick.evaluate(x, &f, &K).ok);
    ASSERT_GT(brick.point().trial().eqps, 0.01);
    const double h = 1e-7;
    double worst = 0.0;
    for (int j = 0; j < 24; ++j) {
      HexCorners xp = x, xm = x;
      xp[static_cast<std::size_t>(j / 3)](j % 3) += h;
      xm[static_cast<std::size_t>(j / 3)](j % 3) -= h;
      HexVector fp, fm;
      ASSERT_TRUE(brick.evaluate(xp, &fp, nullptr).ok);
      ASSERT_TRUE(brick.evaluate(xm, &fm, nullptr).ok);
      worst = std::max(worst, ((fp - fm) / (2.0 * h) - K.col(j)).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-6 * K.cwiseAbs().maxCoeff()) << (kinematic ? "Armstrong-Frederick" : "isotropic");
    const double asymmetry = (K - K.transpose()).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
    if (kinematic) EXPECT_GT(asymmetry, 1e-6);
    else EXPECT_LT(asymmetry, 1e-9);
  }
  }
}

// Patch test at large strain: a distorted 2 x 2 x 2 patch whose nodes all follow one
// homogeneous deformation is in equilibrium at its interior node, and the elements' stresses agree.
TEST(Brick8, LargeStrainPatchInEquilibriumAtTheInteriorNode) {
  const SolidPoint::Law law(aa3003());
  Vec3 nodes[27];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) nodes[9 * k + 3 * j + i] = Vec3(i * 1.0, j * 0.8, k * 0.5);
  nodes[13] += Vec3(0.17, -0.11, 0.09);  // the interior node, moved
  Mat3 F;
  F << 1.3, 0.2, 0.05, -0.1, 0.85, 0.0, 0.04, 0.1, 0.92;
  F = rotation() * F;
  Vec3 force = Vec3::Zero();
  double scale = 0.0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const int base = 9 * k + 3 * j + i;
        const int ids[8] = {base, base + 1, base + 4, base + 3, base + 9, base + 10, base + 13, base + 12};
        HexCorners X;
        int local = -1;
        for (int I = 0; I < 8; ++I) {
          X[static_cast<std::size_t>(I)] = nodes[ids[I]];
          if (ids[I] == 13) local = I;
        }
        Brick8 brick(X, Mat3::Identity(), law);
        HexVector f;
        ASSERT_TRUE(brick.evaluate(map(X, F), &f, nullptr).ok);
        force += f.segment<3>(3 * local);
        scale = std::max(scale, f.cwiseAbs().maxCoeff());
      }
  EXPECT_LT(force.norm(), 1e-12 * scale);
}

TEST(Brick8, RejectsAnInvertedElementAndBadOptions) {
  const SolidPoint::Law law(aa3003());
  const HexCorners X = box(1.0, 1.0, 1.0);
  Brick8 brick(X, Mat3::Identity(), law);
  const BrickStatus s = brick.evaluate(map(X, Vec3(1.0, 1.0, -0.5).asDiagonal().toDenseMatrix()), nullptr, nullptr);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.reason.find("inside out"), std::string::npos) << s.reason;
  EXPECT_LT(s.suggested_scale, 1.0);
  EXPECT_THROW(Brick8(X, Mat3::Identity(), law, HourglassOptions{-1.0, false}), std::invalid_argument);
  EXPECT_THROW(Brick8(X, 2.0 * Mat3::Identity(), law), std::invalid_argument);
}

}  // namespace
}  // namespace spifit::element
