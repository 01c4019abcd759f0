// force_ripple on constructed force histories: a sine of the element period on a linear trend
// over steady travel gives the sine's amplitude exactly (the centred mean over one period removes
// the sine and keeps the trend); a plunge, a corner and increments too coarse to resolve the
// period are not looked at; the warning names the component and the travel.
#include "forward/scenes/common/force_ripple.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace spifit::scene {
namespace {

constexpr double kH = 3.6;  // element size and ripple period [mm]

// A plunge of 5 mm at x = 0 (force rising steeply), then steady travel along +x at z = 0 with
// Fz = 400 + 5 x + a sin(2 pi x / h) and Fx = -60, samples every step mm.
std::vector<ToolForceSample> line_history(double a, double step) {
  std::vector<ToolForceSample> out;
  double travel = 0.0;
  for (int i = 0; i <= 10; ++i) {
    ToolForceSample s;
    s.travel = travel;
    s.centre = {0.0, 0.0, 5.0 - 0.5 * i};
    s.force = {-6.0 * i, 0.0, 40.0 * i};
    out.push_back(s);
    travel += 0.5;
  }
  travel -= 0.5;
  for (double x = step; x <= 30.0 + 1e-9; x += step) {
    ToolForceSample s;
    s.travel = travel + x;
    s.centre = {x, 0.0, 0.0};
    s.force = {-60.0, 0.0, 400.0 + 5.0 * x + a * std::sin(2.0 * std::numbers::pi * x / kH)};
    out.push_back(s);
  }
  return out;
}

double peak(const std::vector<ToolForceSample>& s) {
  double p = 0.0;
  for (const auto& x : s) p = std::max(p, x.force.norm());
  return p;
}

TEST(ForceRipple, ASineOnATrendGivesItsAmplitude) {
  const auto s = line_history(40.0, kH / 12.0);  // 12 samples per period: the crests are sampled
  const ForceRipple r = force_ripple(s, kH);
  EXPECT_GT(r.windows, 80);
  EXPECT_EQ(r.component, 2);
  EXPECT_NEAR(r.amplitude, 40.0 / peak(s), 1e-9);
  EXPECT_NEAR(std::fmod(r.travel - 5.0, kH / 2.0), kH / 4.0, 1e-9);  // at a crest or a trough (x = travel - 5)
  EXPECT_LT(r.amplitude, kRippleWarningFraction);  // 6.8 %: no warning
  EXPECT_TRUE(ripple_warning(r).empty());
}

TEST(ForceRipple, ASmoothForceHasNoneAndThePlungeIsNotLookedAt) {
  const auto s = line_history(0.0, kH / 12.0);
  const ForceRipple r = force_ripple(s, kH);
  EXPECT_GT(r.windows, 80);
  EXPECT_LT(r.amplitude, 1e-12) << "at " << r.travel;  // the plunge's 40 N per sample would be ~7 % of the peak
  EXPECT_TRUE(ripple_warning(r).empty());
}

TEST(ForceRipple, IncrementsCoarserThanASixthOfThePeriodResolveNone) {
  const ForceRipple r = force_ripple(line_history(100.0, kH / 4.0), kH);
  EXPECT_EQ(r.windows, 0);
  EXPECT_EQ(r.amplitude, 0.0);
  EXPECT_TRUE(ripple_warning(r).empty());
}

TEST(ForceRipple, AboveTheThresholdWarns) {
  const ForceRipple r = force_ripple(line_history(120.0, kH / 12.0), kH);
  EXPECT_GT(r.amplitude, kRippleWarningFraction);
  const std::string w = ripple_warning(r);
  EXPECT_EQ(w.rfind("the tool force ripples: Fz departs from its mean over one element length (3.6 mm) by up to 18 % of the peak "
                    "force (at ", 0), 0u) << w;
}

TEST(ForceRipple, ACornerIsNotSteadyTravel) {
  // Along +x, then a right-angle turn to +y with a jump of the force at the corner.
  std::vector<ToolForceSample> s;
  for (int i = 0; i <= 40; ++i) {
    ToolForceSample x;
    x.travel = 0.3 * i;
    x.centre = i <= 20 ? Eigen::Vector3d(0.3 * i, 0, 0) : Eigen::Vector3d(6.0, 0.3 * (i - 20), 0);
    x.force = {0.0, 0.0, i <= 20 ? 400.0 : 300.0};
    s.push_back(x);
  }
  const ForceRipple r = force_ripple(s, kH);
  EXPECT_GT(r.windows, 0);
  EXPECT_LT(r.amplitude, 1e-12);
}

}  // namespace
}  // namespace spifit::scene
