#include "forward/material/hill48.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace spifit::material;

// Thesis eq. C.3 with the measured, rounded r-values of App. C.1.
TEST(Hill48, LankfordRoundedThesisValues) {
  const Hill48 h = hill_from_lankford({0.68, 0.73, 0.66});
  EXPECT_NEAR(h.F, 1.2266, 1e-4);
  EXPECT_NEAR(h.G, 1.1905, 1e-4);
  EXPECT_NEAR(h.H, 0.8095, 1e-4);
  EXPECT_NEAR(h.N, 2.9729, 1e-4);
  EXPECT_DOUBLE_EQ(h.L, h.N);
  EXPECT_DOUBLE_EQ(h.M, h.N);
}

// Table C.2 as printed (F 1.224, G 1.193, H 0.807, N 2.977) follows from unrounded r-values.
TEST(Hill48, LankfordReproducesTableC2) {
  const Hill48 h = hill_from_lankford({0.6765, 0.7317, 0.6593});
  EXPECT_NEAR(h.F, 1.224, 5e-4);
  EXPECT_NEAR(h.G, 1.193, 5e-4);
  EXPECT_NEAR(h.H, 0.807, 5e-4);
  EXPECT_NEAR(h.N, 2.977, 5e-4);
}

TEST(Hill48, LankfordRoundTrip) {
  const Lankford r{0.6765, 0.7317, 0.6593};
  const Lankford back = lankford_from_hill(hill_from_lankford(r));
  EXPECT_NEAR(back.r0, r.r0, 1e-14);
  EXPECT_NEAR(back.r45, r.r45, 1e-14);
  EXPECT_NEAR(back.r90, r.r90, 1e-14);
}

// Card C.3's N = 4.06 predicts r45 = 1.18, not the measured 0.73 (eq. C.2, App. C.1).
TEST(Hill48, CardC3PredictsR45Of118) {
  const Hill48 h{1.224, 1.193, 0.807, 4.06, 4.06, 4.06};
  EXPECT_NEAR(lankford_from_hill(h).r45, 1.1798, 1e-4);
  EXPECT_NEAR(r_value_at_angle(h, std::numbers::pi / 4), lankford_from_hill(h).r45, 1e-14);
  EXPECT_NEAR(r_value_at_angle(h, 0.0), h.H / h.G, 1e-14);
  EXPECT_NEAR(r_value_at_angle(h, std::numbers::pi / 2), h.H / h.F, 1e-14);
}

TEST(Hill48, VonMisesFactors) {
  const Hill48 vm = Hill48::von_mises();
  EXPECT_TRUE(vm.is_von_mises());
  for (double a : {0.0, 0.3, 0.7854, 1.2}) {
    EXPECT_NEAR(uniaxial_stress_factor(vm, a), 1.0, 1e-14);
    EXPECT_NEAR(r_value_at_angle(vm, a), 1.0, 1e-14);
  }
  EXPECT_NEAR(shear_stress_factor(vm), std::sqrt(3.0), 1e-14);
}

// Abaqus writes Hill without the factor 1/2: von Mises has all ratios 1.
TEST(Hill48, AbaqusPotentialVonMisesIsUnity) {
  const AbaqusPotential a = abaqus_potential_from_hill(Hill48::von_mises());
  for (double r : {a.R11, a.R22, a.R33, a.R12, a.R13, a.R23}) EXPECT_NEAR(r, 1.0, 1e-15);
}

TEST(Hill48, AbaqusPotentialCardC3) {
  const Hill48 h{.F = 1.224, .G = 1.193, .H = 0.807, .L = 4.5, .M = 5.0, .N = 4.06};  // distinct L, M, N catch a swap
  const AbaqusPotential a = abaqus_potential_from_hill(h);
  EXPECT_NEAR(a.R11, std::sqrt(2.0 / 2.0), 1e-12);
  EXPECT_NEAR(a.R22, std::sqrt(2.0 / (1.224 + 0.807)), 1e-12);
  EXPECT_NEAR(a.R33, std::sqrt(2.0 / (1.224 + 1.193)), 1e-12);
  EXPECT_NEAR(a.R12, std::sqrt(3.0 / 4.06), 1e-12);
  EXPECT_NEAR(a.R13, std::sqrt(3.0 / 4.5), 1e-12);  // thesis L is xz = Abaqus 13
  EXPECT_NEAR(a.R23, std::sqrt(3.0 / 5.0), 1e-12);  // thesis M is yz = Abaqus 23
  const Hill48 back = hill_from_abaqus_potential(a);
  EXPECT_NEAR(back.F, h.F, 1e-12);
  EXPECT_NEAR(back.G, h.G, 1e-12);
  EXPECT_NEAR(back.H, h.H, 1e-12);
  EXPECT_NEAR(back.N, h.N, 1e-12);
  EXPECT_NEAR(back.L, h.L, 1e-12);
  EXPECT_NEAR(back.M, h.M, 1e-12);
}

// Uniaxial yield along RD in Abaqus is sigma0 * R11; in thesis notation sigma_F / sqrt((G+H)/2).
TEST(Hill48, AbaqusRatiosAreYieldStressRatios) {
  const Hill48 h{1.3, 0.9, 0.7, 3.5, 3.5, 3.5};
  const AbaqusPotential a = abaqus_potential_from_hill(h);
  EXPECT_NEAR(1.0 / uniaxial_stress_factor(h, 0.0), a.R11, 1e-12);
  EXPECT_NEAR(1.0 / uniaxial_stress_factor(h, std::numbers::pi / 2), a.R22, 1e-12);
  EXPECT_NEAR(1.0 / shear_stress_factor(h), a.R12 / std::sqrt(3.0), 1e-12);
}

TEST(Hill48, Convexity) {
  EXPECT_EQ(hill_convexity_violation({1.224, 1.193, 0.807, 4.06, 4.06, 4.06}), "");
  EXPECT_NE(hill_convexity_violation({-1.0, -1.0, 0.5, 3, 3, 3}), "");
  EXPECT_NE(hill_convexity_violation({1, 1, 1, 3, 3, -3}), "");
  // Slightly negative H can still be convex (FG + GH + HF > 0).
  EXPECT_EQ(hill_convexity_violation({1.0, 1.0, -0.2, 3, 3, 3}), "");
}
