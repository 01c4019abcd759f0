// Tensile scene against the closed-form Hill 1948 + Swift solution (card C.3 + C.4) and the
// closed-form von Mises mixed-hardening solutions (docs/design/numerics-material.md).
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/material/hill48.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/closed_form.hpp"
#include "tests/support/scenes.hpp"

#include <gtest/gtest.h>

using namespace spifit;
using spifit::test::deg;

namespace {
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }
}  // namespace

class TensileHillSwift : public ::testing::TestWithParam<double> {};

TEST_P(TensileHillSwift, MatchesClosedForm) {
  const double angle = GetParam();
  const auto card = test::card("aa3003o_c3c4");
  const auto h = card.hill();
  const double hf = material::uniaxial_stress_factor(h, deg(angle));
  const test::UniaxialClosedForm cf{card.params, hf};
  const auto r = scene::run_material_point(card.params, test::tensile(angle));
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(r.curve.size(), 201u);

  // r-value at 10 % strain, eq. for r(alpha) in hill48.hpp.
  ASSERT_TRUE(r.r_value.has_value());
  EXPECT_LT(rel(*r.r_value, material::r_value_at_angle(h, deg(angle))), 1e-6);

  // Initial yield: K eps0^n / h (Kirchhoff, the law's measure).
  ASSERT_FALSE(r.yield_events.empty());
  const double sy0 = material::hardening_stress(card.params, 0.0) / hf;
  EXPECT_LT(rel(r.yield_events.front().stress_kirchhoff, sy0), 1e-6);
  EXPECT_LT(rel(r.yield_events.front().stress, sy0), 1e-3);

  // 0.2 % offset: axial plastic strain 0.002 = h p, so p = 0.002 / h.
  ASSERT_TRUE(r.offset_yield_stress.has_value());
  const double s02 = material::hardening_stress(card.params, 0.002 / hf) / hf;
  EXPECT_LT(rel(*r.offset_yield_stress_kirchhoff, s02), 1e-6);
  EXPECT_LT(rel(*r.offset_yield_stress, s02), 1e-3);

  // The whole curve: Kirchhoff vs log strain to 1e-6, true stress to 1e-3.
  double worst_k = 0.0, worst_t = 0.0;
  for (const auto& p : r.curve) {
    if (p.control_strain == 0.0) continue;
    const double ref = cf.stress(p.control_strain);
    worst_k = std::max(worst_k, rel(p.stress_kirchhoff, ref));
    worst_t = std::max(worst_t, rel(p.stress, ref));
    // Uniaxial stress: no width or shear stress in the loading frame.
    const Eigen::Matrix3d Q = scene::strain_rotation(deg(angle));
    const Eigen::Vector3d sl = Q.transpose() * p.stress_material;
    EXPECT_NEAR(sl(1), 0.0, 1e-9 * ref);
    EXPECT_NEAR(sl(2), 0.0, 1e-9 * ref);
  }
  EXPECT_LT(worst_k, 1e-6);
  EXPECT_LT(worst_t, 1e-3);
  // Plastic strain along the load equals h * eqps (work conjugacy, eq. 3.2).
  const auto& last = r.curve.back();
  const Eigen::Vector3d epl = scene::strain_rotation(deg(angle)).inverse() * last.plastic_strain;
  EXPECT_LT(rel(epl(0), hf * last.eqps), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Angles, TensileHillSwift, ::testing::Values(0.0, 45.0, 90.0, 30.0));

// Von Mises mixed hardening, monotonic uniaxial: AF saturates the offset at 1.5 Xsat,
// Ziegler at CA / GA. The exponential back-stress update is exact for this proportional path.
class TensileVonMisesKinematic : public ::testing::TestWithParam<std::string> {};

TEST_P(TensileVonMisesKinematic, MonotonicAndReverseYield) {
  auto card = test::card(GetParam());
  if (!card.hill().is_von_mises()) card = test::von_mises_copy(card);
  const test::UniaxialClosedForm cf{card.params, 1.0};
  const double eps_rev = 0.2;
  const auto r = scene::run_material_point(card.params, test::tensile(0.0, {eps_rev, 0.1}, 300));
  ASSERT_TRUE(r.ok) << r.message;
  double worst = 0.0;
  for (const auto& p : r.curve) {
    if (p.segment != 0 || p.control_strain == 0.0) continue;
    worst = std::max(worst, rel(p.stress_kirchhoff, cf.stress(p.control_strain)));
  }
  EXPECT_LT(worst, 1e-6) << card.name;

  // Reverse yield at the analytic value: sigma_rev = offset(p1) - sigma_F(p1).
  ASSERT_EQ(r.yield_events.size(), 2u);
  const double p1 = test::plastic_strain_at(cf, eps_rev, eps_rev);
  const double s_rev = cf.offset(p1) - material::hardening_stress(card.params, p1);
  EXPECT_EQ(r.yield_events[1].segment, 1);
  EXPECT_LT(rel(r.yield_events[1].stress_kirchhoff, s_rev), 1e-6) << card.name;
}

INSTANTIATE_TEST_SUITE_P(Cards, TensileVonMisesKinematic,
                         ::testing::Values("aa3003o_c6_ziegler_brick", "aa3003o_c8_ziegler_shell", "aa3003o_c5_af_brick",
                                           "aa3003o_c7_af_shell", "aa3003o_c3c4"));

// The AF saturation limit itself (docs/design/numerics-material.md): offset -> 1.5 Xsat after large strain.
TEST(TensileVonMisesKinematic, ArmstrongFrederickSaturatesAtOnePointFiveXsat) {
  auto card = test::von_mises_copy(test::card("aa3003o_c7_af_shell"));
  const auto r = scene::run_material_point(card.params, test::tensile(0.0, {1.0}, 400));
  ASSERT_TRUE(r.ok);
  const auto& last = r.curve.back();
  const double offset = last.stress_kirchhoff - material::hardening_stress(card.params, last.eqps);
  EXPECT_NEAR(offset, 1.5 * 46.0, 1e-6);
  EXPECT_NEAR(last.back_stress(0), 46.0, 1e-6);   // X_xx -> Xsat
  EXPECT_NEAR(last.back_stress(1), -23.0, 1e-6);  // deviatoric: X_yy = X_zz = -Xsat / 2
  EXPECT_NEAR(last.back_stress(2), -23.0, 1e-6);
}

// Ziegler limit: the back-stress follows sigma - X, which is uniaxial, so X = diag(X11, 0, 0)
// and the offset saturates at CA / GA (= 52.7 MPa for card C.8).
TEST(TensileVonMisesKinematic, ZieglerSaturatesAtCAOverGA) {
  const auto card = test::card("aa3003o_c8_ziegler_shell");
  const auto r = scene::run_material_point(card.params, test::tensile(0.0, {0.5}, 400));
  ASSERT_TRUE(r.ok);
  const auto& last = r.curve.back();
  EXPECT_NEAR(last.back_stress(0), 3000.0 / 56.9, 1e-6);
  EXPECT_NEAR(last.back_stress(1), 0.0, 1e-9);
  EXPECT_NEAR(last.back_stress(2), 0.0, 1e-9);
}
