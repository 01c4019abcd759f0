#pragma once
// What the solid elements' sensitivity tests share: a distorted, turned element, a path of
// corner motions that stretches, bends and shears it into plasticity and partly back (with an
// extra motion of each corner in proportion to the path, the parameter s of slot 4), and the
// comparison of an element's total derivatives along it, load + K du, with central differences
// of whole paths.
#include "forward/element/solid_element.hpp"
#include "tests/support/hex_elements.hpp"
#include "tests/support/path_seeds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace spifit::element::test {

using SolidFactory = std::function<std::unique_ptr<SolidElement>(const SolidPoint::Law&)>;

inline HexCorners path_reference() {
  HexCorners X = box(2.0, 1.5, 0.6);
  X[1] += Eigen::Vector3d(0.2, -0.1, 0.05);
  X[6] += Eigen::Vector3d(0.1, 0.05, -0.08);
  return X;
}

inline Eigen::Matrix3d path_axes() { return Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

// The path's share at time t (0 to 6): loading up to t = 4, then partly back.
inline double path_amount(double t) { return t <= 4.0 ? t / 4.0 : 1.0 - 0.4 * (t - 4.0); }
inline Eigen::Vector3d path_extra_motion(int I) { return Eigen::Vector3d(0.03 * I - 0.1, 0.02 * (I % 3), 0.01 * (I % 2) - 0.004 * I); }

inline HexCorners path_configuration(double time, double s, double scale = 1.0) {
  const HexCorners X = path_reference();
  const double t = scale * path_amount(time), stretch = 0.04 * t, kappa = 0.05 * t, shear = 0.02 * t;
  HexCorners x;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d& p = X[static_cast<std::size_t>(i)];
    const double xc = p.x() - 1.0, zc = p.z() - 0.3;
    x[static_cast<std::size_t>(i)] = p + Eigen::Vector3d(stretch * p.x() - kappa * xc * zc + shear * p.y(), -0.3 * stretch * p.y(), 0.5 * kappa * xc * xc) +
                                     (s * t) * path_extra_motion(i);
  }
  return x;
}

inline HexSensitivities path_motion_derivative(double time, int slot, double scale = 1.0) {
  HexSensitivities du = HexSensitivities::Zero();
  for (int i = 0; i < 8; ++i) du.block<3, 1>(3 * i, slot) = scale * path_amount(time) * path_extra_motion(i);
  return du;
}

// The element's forces along the path (path_configuration) with card p and path parameter s.
inline std::vector<HexVector> path_forces(const SolidFactory& make, const material::MaterialParams<double>& p, double s, int substeps, double scale) {
  const SolidPoint::Law law(p);
  const std::unique_ptr<SolidElement> el = make(law);
  std::vector<HexVector> out;
  for (int n = 1; n <= 6 * substeps; ++n) {
    HexVector f;
    const PointStatus st = el->evaluate(path_configuration(static_cast<double>(n) / substeps, s, scale), &f, nullptr);
    EXPECT_TRUE(st.ok) << "increment " << n << ": " << st.reason;
    el->commit();
    out.push_back(f);
  }
  return out;
}

// The exact derivatives of the forces along the path in 6 substeps increments, its strains
// scaled by scale (Swift K, n, AF C_X, E, the path's s, nu), against central differences;
// returns the element at the path's end.
inline std::unique_ptr<SolidElement> expect_path_derivatives_match(const SolidFactory& make, int substeps = 1, double scale = 1.0) {
  constexpr int kSlots = 6;
  const material::MaterialParams<double> p = aa3003_af();
  const SolidPoint::Law law(p);
  const SolidSensitivityLaw slaw(material::seeded_params(p, spifit::test::path_seeds(p)));
  std::unique_ptr<SolidElement> el = make(law);
  el->enable_sensitivities(slaw, kSlots);
  std::vector<Eigen::Matrix<double, 24, kSlots>> ddm;
  for (int n = 1; n <= 6 * substeps; ++n) {
    const double time = static_cast<double>(n) / substeps;
    const HexCorners x = path_configuration(time, 0.0, scale);
    HexVector f;
    HexMatrix k;
    const PointStatus st = el->evaluate(x, &f, &k);
    EXPECT_TRUE(st.ok) << "increment " << n << ": " << st.reason;
    HexSensitivities load;
    const HexSensitivities du = path_motion_derivative(time, 4, scale);
    EXPECT_TRUE(el->sensitivities(x, slaw, nullptr, &load).ok);
    EXPECT_TRUE(el->sensitivities(x, slaw, &du, nullptr).ok);
    ddm.push_back(load.leftCols<kSlots>() + k * du.leftCols<kSlots>());
    el->commit();
  }
  EXPECT_GT(el->max_eqps(), 0.02 * scale);
  spifit::test::expect_path_slots_match<HexVector>(
      p, ddm, kSlots, [&](const material::MaterialParams<double>& q, double s) { return path_forces(make, q, s, substeps, scale); },
      [](std::size_t, const HexVector& v) { return v; });
  return el;
}

// The thickness ratio's derivative along the corners' motion, against central differences.
inline void expect_thickness_ratio_follows_the_corners(const SolidFactory& make) {
  const material::MaterialParams<double> p = aa3003();
  const SolidPoint::Law law(p);
  const SolidSensitivityLaw slaw(material::seeded_params(p, {}), {}, 1);
  const std::unique_ptr<SolidElement> el = make(law);
  el->enable_sensitivities(slaw, 1);
  const int n = 3;
  const HexCorners x = path_configuration(n, 0.0);
  ASSERT_TRUE(el->evaluate(x, nullptr, nullptr).ok);
  HexSensitivities load;
  const HexSensitivities du = path_motion_derivative(n, 0);
  ASSERT_TRUE(el->sensitivities(x, slaw, nullptr, &load).ok);
  ASSERT_TRUE(el->sensitivities(x, slaw, &du, nullptr).ok);
  el->commit();
  const double exact = el->thickness_ratio_sensitivity()(0);
  const auto ratio = [&](double s) {
    const std::unique_ptr<SolidElement> e = make(law);
    EXPECT_TRUE(e->evaluate(path_configuration(n, s), nullptr, nullptr).ok);
    e->commit();
    return e->thickness_ratio();
  };
  const double h = 1e-5, cd = (ratio(h) - ratio(-h)) / (2.0 * h);
  EXPECT_GT(std::abs(cd), 1e-3);
  EXPECT_NEAR(exact, cd, 1e-8 * std::abs(cd) + 1e-10);
}

}  // namespace spifit::element::test
