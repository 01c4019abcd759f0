// Simple shear along RD (alpha = 0) for every card against the closed form
// tau = sigma_F(p)/sqrt(N) + Xxy(p), gamma = tau/mu + sqrt(N) p, and the Bauschinger reverse
// yield tau_rev = Xxy(p1) - sigma_F(p1)/sqrt(N).
#include "forward/material/hardening/hardening_laws.hpp"
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/closed_form.hpp"
#include "tests/support/scenes.hpp"

#include <gtest/gtest.h>

using namespace spifit;

namespace {
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }
}  // namespace

TEST(Shear, SmallStrainMatchesClosedFormEveryCard) {
  for (const auto& card : test::all_test_cards()) {
    SCOPED_TRACE(card.name);
    const test::ShearClosedForm cf{card.params};
    const auto r = scene::run_material_point(card.params, test::shear(0.0, {0.05}, 100));
    ASSERT_TRUE(r.ok) << r.message;
    double worst = 0.0;
    for (const auto& p : r.curve) {
      if (p.control_strain == 0.0) continue;
      worst = std::max(worst, rel(p.stress_kirchhoff, cf.stress(p.control_strain)));
      EXPECT_NEAR(p.stress, p.stress_kirchhoff, 1e-12 * std::abs(p.stress));  // no volume change
      EXPECT_NEAR(p.stress_material(0), 0.0, 1e-9);  // pure shear: no normal stress
    }
    EXPECT_LT(worst, 1e-6);
    if (card.params.plastic) {
      ASSERT_EQ(r.yield_events.size(), 1u);
      EXPECT_LT(rel(r.yield_events[0].stress_kirchhoff, cf.stress_at_p(0.0)), 1e-9);
    }
  }
}

TEST(Bauschinger, ReverseYieldEveryPlasticCard) {
  for (const auto& card : test::all_test_cards()) {
    if (!card.params.plastic) continue;
    SCOPED_TRACE(card.name);
    const test::ShearClosedForm cf{card.params};
    const double g1 = 0.05;
    const auto r = scene::run_material_point(card.params, test::shear(0.0, {g1, -g1, g1}, 300));
    ASSERT_TRUE(r.ok) << r.message;
    ASSERT_EQ(r.yield_events.size(), 3u);  // forward, reverse, re-loading
    const double p1 = test::plastic_strain_at(cf, g1, g1);
    const double tau_rev = cf.back_stress(p1) - material::hardening_stress(card.params, p1) / std::sqrt(card.params.N);
    EXPECT_LT(rel(r.yield_events[1].stress_kirchhoff, tau_rev), 1e-6);
    // The cumulative strain is a monotone abscissa through the reversals.
    for (std::size_t i = 1; i < r.curve.size(); ++i) EXPECT_GT(r.curve[i].cumulative_strain, r.curve[i - 1].cumulative_strain);
    EXPECT_NEAR(r.curve.back().cumulative_strain, 5 * g1, 1e-12);
  }
}
