#include "forward/element/shell_section.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace spifit::element {
namespace {

material::MaterialParams<double> aa3003() {  // card C.3 + C.4
  material::MaterialParams<double> p;
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;
  return p;
}

TEST(ShellSection, ThicknessFollowsConstantVolumeAfterCommit) {
  const material::ReturnMapping<double, 3> law(aa3003());
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellSection s(law, rule, 1.2);
  const double l1 = 1.5, l2 = 1.1;  // in-plane stretches
  const Vec3 e(0.5 * (l1 * l1 - 1.0), 0.5 * (l2 * l2 - 1.0), 0.0);
  Vec6 r;
  ASSERT_TRUE(s.update(e, Vec3::Zero(), &r, nullptr).ok);
  EXPECT_DOUBLE_EQ(s.thickness(), 1.2);  // not before the increment is committed
  s.commit();
  EXPECT_NEAR(s.thickness(), 1.2 / (l1 * l2), 1e-14);
}

TEST(ShellSection, NextIncrementStartsWithoutJumpAndWithTheConvergedTangent) {
  const material::ReturnMapping<double, 3> law(aa3003());
  const ThicknessRule rule = gauss_legendre_rule(5);
  ShellSection s(law, rule, 1.2);
  const Vec3 e(0.08, -0.02, 0.01), kappa(0.05, 0.0, 0.01);  // plastic, with membrane thinning
  Vec6 r1;
  Mat6 k1;
  ASSERT_TRUE(s.update(e, kappa, &r1, &k1).ok);
  s.commit();
  ASSERT_LT(s.thickness(), 1.2);  // the lever arm changed at commit
  // Same strains again: no strain increment in any layer (the reference log strains were
  // re-evaluated with the new lever arm), so every layer keeps its stress exactly, and the
  // tangent is the converged (elastic-plastic) one, not the elastic one.
  Vec6 r2;
  Mat6 k2;
  ASSERT_TRUE(s.update(e, kappa, &r2, &k2).ok);
  for (int l = 0; l < s.layers(); ++l) {
    EXPECT_GT(s.layer_state(l).eqps, 0.0);
    EXPECT_LT((s.layer_trial_state(l).stress - s.layer_state(l).stress).norm(), 1e-9 * s.layer_state(l).stress.norm()) << l;
  }
  // Elastic section stiffness for comparison: the converged (plastic) one is far softer.
  ShellSection fresh(law, rule, 1.2);
  Vec6 r0;
  Mat6 k0;
  ASSERT_TRUE(fresh.update(Vec3::Zero(), Vec3::Zero(), &r0, &k0).ok);
  std::printf("membrane stiffness: converged state %.1f, elastic %.1f N/mm\n", k2(0, 0), k0(0, 0));
  EXPECT_LT(k2(0, 0), 0.05 * k0(0, 0));  // 0.0025 with the converged tangent, 0.32 without it
}

}  // namespace
}  // namespace spifit::element
