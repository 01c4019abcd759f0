// Direct differentiation through the one-point brick: the total derivative of its forces along a
// path of corner motions, load + K du, against central differences of whole paths with perturbed
// parameters (the law's, and one the corners' motion depends on). The path stretches, bends (an
// hourglass mode) and shears the element into plasticity and partly back, so that the centre's
// state, the hourglass forces and the stabilisation built on the consistent tangent all carry
// history.
#include "forward/element/brick8.hpp"
#include "tests/support/central_differences.hpp"
#include "tests/support/hex_elements.hpp"
#include "tests/support/path_seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace spifit::element {
namespace {

using material::FieldSeed;

constexpr int kSlots = 6;  // Swift K, n, AF CX, E; slot 4 moves the corners; slot 5 nu

HexCorners reference() {
  HexCorners X = test::box(2.0, 1.5, 0.6);
  X[1] += Eigen::Vector3d(0.2, -0.1, 0.05);
  X[6] += Eigen::Vector3d(0.1, 0.05, -0.08);
  return X;
}

Eigen::Matrix3d turned_axes() { return Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

// Increment n of the path at parameter s: stretch, bend and shear into plasticity, then partly
// back; s adds a motion v_I of each corner, in proportion to the path.
double amount(int n) { return n <= 4 ? n / 4.0 : 1.0 - 0.4 * (n - 4); }
Eigen::Vector3d extra_motion(int I) { return Eigen::Vector3d(0.03 * I - 0.1, 0.02 * (I % 3), 0.01 * (I % 2) - 0.004 * I); }

HexCorners configuration(int n, double s) {
  const HexCorners X = reference();
  const double t = amount(n), stretch = 0.04 * t, kappa = 0.05 * t, shear = 0.02 * t;
  HexCorners x;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d& p = X[static_cast<std::size_t>(i)];
    const double xc = p.x() - 1.0, zc = p.z() - 0.3;
    x[static_cast<std::size_t>(i)] = p + Eigen::Vector3d(stretch * p.x() - kappa * xc * zc + shear * p.y(), -0.3 * stretch * p.y(), 0.5 * kappa * xc * xc) +
                                     (s * t) * extra_motion(i);
  }
  return x;
}

std::vector<HexVector> forces(const material::MaterialParams<double>& p, double s, const HourglassOptions& o) {
  const SolidPoint::Law law(p);
  Brick8 brick(reference(), turned_axes(), law, o);
  std::vector<HexVector> out;
  for (int n = 1; n <= 6; ++n) {
    HexVector f;
    EXPECT_TRUE(brick.evaluate(configuration(n, s), &f, nullptr).ok);
    brick.commit();
    out.push_back(f);
  }
  return out;
}

void expect_path_derivatives_match(const HourglassOptions& o) {
  const material::MaterialParams<double> p = test::aa3003_af();
  const SolidPoint::Law law(p);
  const std::vector<FieldSeed> sd = spifit::test::path_seeds(p);
  const SensLaw6 slaw(material::seeded_params(p, sd));
  Brick8 brick(reference(), turned_axes(), law, o);
  brick.enable_sensitivities(slaw, kSlots);
  std::vector<Eigen::Matrix<double, 24, kSlots>> ddm;
  std::vector<double> thickness;
  for (int n = 1; n <= 6; ++n) {
    const HexCorners x = configuration(n, 0.0);
    HexVector f;
    HexMatrix k;
    ASSERT_TRUE(brick.evaluate(x, &f, &k).ok);
    HexSensitivities load, du = HexSensitivities::Zero();
    ASSERT_TRUE(brick.sensitivities(x, slaw, nullptr, &load).ok);
    for (int i = 0; i < 8; ++i) du.block<3, 1>(3 * i, 4) = amount(n) * extra_motion(i);
    ASSERT_TRUE(brick.sensitivities(x, slaw, &du, nullptr).ok);
    ddm.push_back(load.leftCols<kSlots>() + k * du.leftCols<kSlots>());
    brick.commit();
  }
  EXPECT_GT(brick.point().committed().eqps, 0.02);
  EXPECT_GT(brick.hourglass_amplitudes().norm(), 1e-3);  // the bending carries the hourglass forces
  spifit::test::expect_path_slots_match<HexVector>(
      p, ddm, kSlots, [&](const material::MaterialParams<double>& q, double s) { return forces(q, s, o); },
      [](std::size_t, const HexVector& v) { return v; });
}

TEST(Brick8Sensitivity, ForceDerivativesMatchCentralDifferencesAlongAPath) { expect_path_derivatives_match(HourglassOptions{}); }

TEST(Brick8Sensitivity, WithAnElasticStabilisation) { expect_path_derivatives_match(HourglassOptions{1.0, true}); }

// The thickness ratio's derivative along the corners' motion, against central differences.
TEST(Brick8Sensitivity, ThicknessRatioFollowsTheCorners) {
  const material::MaterialParams<double> p = test::aa3003();
  const SolidPoint::Law law(p);
  const SensLaw6 slaw(material::seeded_params(p, {}));
  Brick8 brick(reference(), turned_axes(), law);
  brick.enable_sensitivities(slaw, 1);
  const int n = 3;
  const HexCorners x = configuration(n, 0.0);
  ASSERT_TRUE(brick.evaluate(x, nullptr, nullptr).ok);
  HexSensitivities du = HexSensitivities::Zero();
  for (int i = 0; i < 8; ++i) du.block<3, 1>(3 * i, 0) = amount(n) * extra_motion(i);
  ASSERT_TRUE(brick.sensitivities(x, slaw, &du, nullptr).ok);
  brick.commit();
  const double exact = brick.thickness_ratio_sensitivity()(0);
  const auto ratio = [&](double s) {
    Brick8 b(reference(), turned_axes(), law);
    EXPECT_TRUE(b.evaluate(configuration(n, s), nullptr, nullptr).ok);
    b.commit();
    return b.thickness_ratio();
  };
  const double h = 1e-5, cd = (ratio(h) - ratio(-h)) / (2.0 * h);
  EXPECT_GT(std::abs(cd), 1e-3);
  EXPECT_NEAR(exact, cd, 1e-8 * std::abs(cd) + 1e-10);
}

}  // namespace
}  // namespace spifit::element
