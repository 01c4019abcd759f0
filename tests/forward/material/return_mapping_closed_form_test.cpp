// Single-step exactness of the return mapping where the exact answer is known.
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/return_mapping.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/closed_form.hpp"

#include <gtest/gtest.h>

using namespace spifit::material;

// 3D uniaxial stress path (lateral strains chosen from the closed form) in ONE increment:
// isotropic hardening and von Mises AF/Ziegler are integrated exactly along proportional paths.
TEST(ReturnMapping, OneStepUniaxialIsExactForProportionalLoading) {
  for (const char* name : {"aa3003o_c6_ziegler_brick", "aa3003o_c8_ziegler_shell", "aa3003o_c3c4"}) {
    SCOPED_TRACE(name);
    auto card = spifit::test::card(name);
    card = spifit::test::von_mises_copy(card);
    const spifit::test::UniaxialClosedForm cf{card.params, 1.0};
    const double p = 0.15;
    const double s = cf.stress_at_p(p);
    const double e_axial = s / card.params.E + p;
    const double e_lat = -card.params.nu * s / card.params.E - 0.5 * p;
    const ReturnMapping<double, 6> law(card.params);
    MaterialState<double, 6> s0, s1;
    Eigen::Matrix<double, 6, 1> de;
    de << e_axial, e_lat, e_lat, 0, 0, 0;
    ASSERT_TRUE(law.integrate(s0, de, s1, nullptr).ok());
    EXPECT_NEAR(s1.stress(0), s, 1e-9 * s);
    EXPECT_NEAR(s1.stress(1), 0.0, 1e-9 * s);
    EXPECT_NEAR(s1.eqps, p, 1e-12);
  }
}

// Perfect plasticity (n = 0): the stress stays on sigma_eq = K however far it is pushed.
TEST(ReturnMapping, PerfectPlasticity) {
  auto card = spifit::test::card("aa3003o_c3c4");
  card.params.hardening[SwiftHardening::n] = 0.0;
  card.params.hardening[SwiftHardening::K] = 100.0;
  const ReturnMapping<double, 3> law(card.params);
  MaterialState<double, 3> s0, s1;
  ASSERT_TRUE(law.integrate(s0, Eigen::Vector3d(0.5, -0.2, 0.3), s1, nullptr).ok());
  EXPECT_NEAR(law.equivalent_stress(s1.stress), 100.0, 1e-10);
}

// Elastic-only card: linear, no plastic strain, tangent = C.
TEST(ReturnMapping, ElasticOnly) {
  auto card = spifit::test::card("aa3003o_c3c4");
  card.params.plastic = false;
  const ReturnMapping<double, 3> law(card.params);
  MaterialState<double, 3> s0, s1;
  Eigen::Matrix3d D;
  ASSERT_TRUE(law.integrate(s0, Eigen::Vector3d(0.5, -0.2, 0.3), s1, &D).ok());
  EXPECT_NEAR(s1.stress(0), 72600.0 / (1 - 0.36 * 0.36) * (0.5 - 0.36 * 0.2), 1e-8);
  EXPECT_EQ(s1.eqps, 0.0);
  EXPECT_EQ((D - law.elastic_matrix()).norm(), 0.0);
}

// A non-finite increment fails with a status instead of throwing.
TEST(ReturnMapping, NonFiniteInputReportsFailure) {
  const auto card = spifit::test::card("aa3003o_c3c4");
  const ReturnMapping<double, 3> law(card.params);
  MaterialState<double, 3> s0, s1;
  const auto r = law.integrate(s0, Eigen::Vector3d(std::nan(""), 0, 0), s1, nullptr);
  EXPECT_FALSE(r.ok());
  EXPECT_LT(r.suggested_scale, 1.0);
}
