// Hill + Armstrong-Frederick has no closed form (the flow direction turns as X grows):
// the default scene must match a converged fine-step integration of the same law to 1e-4.
#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"

#include <gtest/gtest.h>

using namespace spifit;

namespace {

// Max relative stress difference at the coarse curve's points (the fine run has an integer
// multiple of the increments, so every coarse point is also a fine point).
double compare(const scene::MaterialPointResult<double>& coarse, const scene::MaterialPointResult<double>& fine, int ratio) {
  double worst = 0.0, scale = 0.0;
  for (const auto& p : fine.curve) scale = std::max(scale, std::abs(p.stress));
  for (std::size_t i = 0; i < coarse.curve.size(); ++i) {
    const auto& c = coarse.curve[i];
    const auto& f = fine.curve[i * ratio];
    EXPECT_NEAR(c.control_strain, f.control_strain, 1e-12);
    worst = std::max(worst, std::abs(c.stress - f.stress) / scale);
  }
  return worst;
}

scene::MaterialPointSetup fine(scene::MaterialPointSetup s, int ratio) {
  s.increments *= ratio;
  s.driver.kinematic_substep = 1e-4;
  return s;
}

}  // namespace

class HillArmstrongFrederick : public ::testing::TestWithParam<std::string> {};

TEST_P(HillArmstrongFrederick, TensileMatchesFineStepIntegration) {
  const auto card = test::card(GetParam());
  for (double angle : {0.0, 45.0, 90.0}) {
    SCOPED_TRACE(angle);
    const auto s = test::tensile(angle, {0.3, 0.15}, 180);  // 120 + 60 increments
    const auto coarse = scene::run_material_point(card.params, s);
    const auto ref = scene::run_material_point(card.params, fine(s, 20));
    ASSERT_TRUE(coarse.ok && ref.ok);
    const double err = compare(coarse, ref, 20);
    EXPECT_LT(err, 1e-4);
    EXPECT_LT(std::abs(*coarse.r_value - *ref.r_value), 1e-4 * *ref.r_value);
    RecordProperty("tensile_rel_error_" + std::to_string(int(angle)), std::to_string(err));
  }
}

TEST_P(HillArmstrongFrederick, BauschingerMatchesFineStepIntegration) {
  const auto card = test::card(GetParam());
  const auto s = test::shear(0.0, {0.3, -0.3, 0.3});
  const auto coarse = scene::run_material_point(card.params, s);
  const auto ref = scene::run_material_point(card.params, fine(s, 20));
  ASSERT_TRUE(coarse.ok && ref.ok);
  EXPECT_LT(compare(coarse, ref, 20), 1e-4);
  // Also at 45 deg, where Hill couples the shear and normal components.
  const auto s45 = test::shear(45.0, {0.3, -0.3}, 150);  // 50 + 100 increments
  const auto c45 = scene::run_material_point(card.params, s45);
  const auto r45 = scene::run_material_point(card.params, fine(s45, 20));
  ASSERT_TRUE(c45.ok && r45.ok);
  EXPECT_LT(compare(c45, r45, 20), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Cards, HillArmstrongFrederick,
                         ::testing::Values("aa3003o_c5_af_brick", "aa3003o_c7_af_shell", "aa3003o_c7n_af_shell"));

// The accuracy control is real: without it (kinematic_substep = 0, one step per increment)
// the same comparison is worse, and with it sub-steps are taken.
TEST(HillArmstrongFrederick, SubsteppingControlsTheError) {
  const auto card = test::card("aa3003o_c7_af_shell");
  auto s = test::tensile(45.0, {0.3}, 20);
  const auto ref = scene::run_material_point(card.params, fine(s, 100));
  const auto with = scene::run_material_point(card.params, s);
  s.driver.kinematic_substep = 0.0;
  const auto without = scene::run_material_point(card.params, s);
  ASSERT_TRUE(ref.ok && with.ok && without.ok);
  EXPECT_GT(with.substeps, without.substeps);
  EXPECT_LT(compare(with, ref, 100), compare(without, ref, 100));
}
