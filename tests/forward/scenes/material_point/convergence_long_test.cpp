// Long checks (label "long", run on demand): every card at every 15 deg, tension-compression
// cycles with large increments, against fine-step references.
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"

#include <gtest/gtest.h>

using namespace spifit;

TEST(LongMaterialPoint, EveryCardEveryAngleCyclic) {
  for (const auto& card : test::all_test_cards()) {
    for (double angle = 0.0; angle <= 180.0; angle += 15.0) {
      SCOPED_TRACE(card.name + " at " + std::to_string(angle));
      auto s = test::tensile(angle, {0.3, -0.1, 0.4}, 240);  // 60 + 80 + 100 increments
      const auto coarse = scene::run_material_point(card.params, s);
      s.increments = 240 * 20;
      s.driver.kinematic_substep = 1e-4;
      const auto fine = scene::run_material_point(card.params, s);
      ASSERT_TRUE(coarse.ok && fine.ok) << coarse.message << fine.message;
      double scale = 0.0, worst = 0.0;
      for (const auto& p : fine.curve) scale = std::max(scale, std::abs(p.stress));
      for (std::size_t i = 0; i < coarse.curve.size(); ++i) {
        ASSERT_NEAR(coarse.curve[i].control_strain, fine.curve[20 * i].control_strain, 1e-12);
        worst = std::max(worst, std::abs(coarse.curve[i].stress - fine.curve[20 * i].stress));
      }
      EXPECT_LT(worst / scale, 1e-4);
    }
  }
}
