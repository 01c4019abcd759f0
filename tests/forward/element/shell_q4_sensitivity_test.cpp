// Direct differentiation through the shell element: the total derivative of the residual along
// a path of nodal motions, load + K du, against central differences of whole paths with
// perturbed parameters (the law's, and one the nodal motion depends on).
#include "forward/element/director.hpp"
#include "forward/element/shell_q4.hpp"
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

constexpr int kSlots = 6;  // Swift K, n, AF CX, E; slot 4 moves the nodes; slot 5 nu

// A distorted, slightly warped quad with non-parallel directors.
const NodeVectors kX = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(2.2, 0.1, 0.05), Eigen::Vector3d(2.0, 1.9, -0.04),
                        Eigen::Vector3d(-0.2, 1.7, 0.02)};
const NodeVectors kD = {Eigen::Vector3d(0.02, -0.01, 1.0).normalized(), Eigen::Vector3d(-0.03, 0.0, 1.0).normalized(),
                        Eigen::Vector3d(0.0, 0.04, 1.0).normalized(), Eigen::Vector3d(0.01, 0.02, 1.0).normalized()};

// Increment n of the path at parameter s: stretch and bend into plasticity, then partly back;
// s adds a motion v_I and a rotation w_I of each node, in proportion to the path.
double amount(int n) { return n <= 4 ? n / 4.0 : 1.0 - 0.4 * (n - 4); }
Eigen::Vector3d extra_motion(int I) { return Eigen::Vector3d(0.3 * I - 0.4, 0.1 * (I % 2), 0.05 * I); }
Eigen::Vector3d extra_rotation(int I) { return Eigen::Vector3d(0.1 - 0.05 * I, 0.08 * (I % 3), 0.02); }

void configuration(int n, double s, NodeVectors* x, NodeVectors* d) {
  const double t = amount(n), stretch = 0.04 * t, b = 0.05 * t;
  for (int i = 0; i < 4; ++i) {
    const auto I = static_cast<std::size_t>(i);
    const Eigen::Vector3d& p = kX[I];
    (*x)[I] = Eigen::Vector3d(p.x() * (1.0 + stretch), p.y() * (1.0 - 0.3 * stretch) + 0.2 * stretch * p.x(),
                              p.z() + b * (p.x() * p.x() - 0.5 * p.y() * p.y())) +
              (s * t) * extra_motion(i);
    const Eigen::Vector3d tilt(b * p.y(), -2.0 * b * p.x(), 0.0);
    (*d)[I] = rotate_by_vector(rotate_by_vector(kD[I], tilt), (s * t) * extra_rotation(i));
  }
}

std::vector<Vec24> residuals(const material::MaterialParams<double>& p, double s, const ShellOptions& o) {
  const material::ReturnMapping<double, 3> law(p);
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellQ4 el(kX, kD, 0.4, law, rule, o);
  std::vector<Vec24> out;
  for (int n = 1; n <= 6; ++n) {
    NodeVectors x, d;
    configuration(n, s, &x, &d);
    Vec24 r;
    EXPECT_TRUE(el.compute(x, d, &r, nullptr).ok);
    el.commit();
    out.push_back(r);
  }
  return out;
}

void expect_path_derivatives_match(const ShellOptions& o) {
  const material::MaterialParams<double> p = test::aa3003_af();
  const material::ReturnMapping<double, 3> law(p);
  const std::vector<FieldSeed> sd = spifit::test::path_seeds(p);
  const SensLaw slaw(material::seeded_params(p, sd));
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellQ4 el(kX, kD, 0.4, law, rule, o);
  el.enable_sensitivities();
  std::vector<Eigen::Matrix<double, 24, kSlots>> ddm;
  std::vector<Mat24> projections;
  for (int n = 1; n <= 6; ++n) {
    NodeVectors x, d;
    configuration(n, 0.0, &x, &d);
    Vec24 r;
    Mat24 k;
    ASSERT_TRUE(el.compute(x, d, &r, &k).ok);
    SensDofs load, du = SensDofs::Zero();
    ASSERT_TRUE(el.sensitivities(x, d, slaw, nullptr, &load).ok);
    const double t = amount(n);
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d& di = d[static_cast<std::size_t>(i)];
      du.block<3, 1>(6 * i, 4) = t * extra_motion(i);
      // The rotation that moves the director, normal to it (the drilling part moves nothing).
      du.block<3, 1>(6 * i + 3, 4) = t * (extra_rotation(i) - extra_rotation(i).dot(di) * di);
    }
    ASSERT_TRUE(el.sensitivities(x, d, slaw, &du, nullptr).ok);
    // The moments about the directors are zero at every configuration, but not their
    // derivatives along the moving directors, which the tangent leaves out (shell_q4.hpp): both
    // sides are compared normal to the directors.
    Mat24 P = Mat24::Identity();
    for (int i = 0; i < 4; ++i) P.block<3, 3>(6 * i + 3, 6 * i + 3) -= d[static_cast<std::size_t>(i)] * d[static_cast<std::size_t>(i)].transpose();
    projections.push_back(P);
    ddm.push_back(P * (load.leftCols<kSlots>() + k * du.leftCols<kSlots>()));
    el.commit();
  }
  EXPECT_GT(el.section(0).layer_state(4).eqps, 0.005);
  spifit::test::expect_path_slots_match<Vec24>(
      p, ddm, kSlots, [&](const material::MaterialParams<double>& q, double s) { return residuals(q, s, o); },
      [&](std::size_t n, const Vec24& v) { return Vec24(projections[n] * v); });
}

TEST(ShellQ4Sensitivity, ResidualDerivativesMatchCentralDifferencesAlongAPath) { expect_path_derivatives_match(ShellOptions{}); }

// The one-point element: the centre's section over the whole area, and the hourglass stiffness,
// which moves with E (slot 3) through the law's elasticity.
TEST(ShellQ4Sensitivity, OnePointElementDerivativesMatchCentralDifferencesAlongAPath) {
  ShellOptions o;
  o.hourglass_stiffness = 0.03;
  expect_path_derivatives_match(o);
}

}  // namespace
}  // namespace spifit::element
