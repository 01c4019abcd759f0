// The law the Abaqus deck encodes (reports::exported_equivalent_card), run through spifit's own
// integrator, reproduces the card: exactly for the RD normalisation (G + H != 2), Ziegler (any
// Hill) and von Mises + Armstrong-Frederick; approximately for Hill + Armstrong-Frederick
// (measured). Tensile curves at 0, 30, 45 and 90 deg with a reversal and simple shear compare
// the two laws' Kirchhoff stresses point by point.
#include "reports/card_export.hpp"

#include "forward/scenes/material_point/material_point_run.hpp"
#include "tests/support/cards.hpp"
#include "tests/support/scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace spifit;
using material::MaterialCard;

namespace {

double max_curve_difference(const MaterialCard& a, const MaterialCard& b, const scene::MaterialPointSetup& s,
                            double* peak) {
  auto sa = s, sb = s;
  sa.want_r_value = sb.want_r_value = false;
  sa.want_offset_yield = sb.want_offset_yield = false;
  const auto ra = scene::run_material_point(a.params, sa);
  const auto rb = scene::run_material_point(b.params, sb);
  EXPECT_TRUE(ra.ok && rb.ok);
  EXPECT_EQ(ra.curve.size(), rb.curve.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(ra.curve.size(), rb.curve.size()); ++i) {
    worst = std::max(worst, std::abs(ra.curve[i].stress_kirchhoff - rb.curve[i].stress_kirchhoff));
    *peak = std::max(*peak, std::abs(ra.curve[i].stress_kirchhoff));
  }
  return worst;
}

double worst_over_scenes(const MaterialCard& a, const MaterialCard& b, double* peak) {
  double worst = 0.0;
  *peak = 0.0;
  for (double angle : {0.0, 45.0, 90.0, 30.0}) {
    worst = std::max(worst, max_curve_difference(a, b, test::tensile(angle, {0.2, 0.1}, 300), peak));
  }
  worst = std::max(worst, max_curve_difference(a, b, test::shear(0.0, {0.2, -0.1}, 300), peak));
  worst = std::max(worst, max_curve_difference(a, b, test::shear(45.0, {0.2}, 200), peak));
  return worst;
}

}  // namespace

TEST(CardExportEquivalence, ExactWhereClaimed) {
  std::vector<MaterialCard> cards = {test::card("aa3003o_c3c4"), test::card("aa3003o_c8_ziegler_shell"),
                                     test::card("aa3003o_c6_ziegler_brick"),
                                     test::von_mises_copy(test::card("aa3003o_c7_af_shell")),
                                     test::von_mises_copy(test::card("aa3003o_c5_af_brick"))};
  // G + H != 2 with isotropic and with Ziegler hardening (and L, M != N).
  auto c = test::card("aa3003o_c3c4");
  c.name = "hill_gh_1.9997";
  c.params.H = 0.8067;
  c.params.L = 3.5;
  c.params.M = 4.5;
  cards.push_back(c);
  auto z = test::card("aa3003o_c8_ziegler_shell");
  z.name = "hill_ziegler";
  z.set_hill(c.hill());
  cards.push_back(z);
  for (const auto& card : cards) {
    const auto eq = reports::exported_equivalent_card(card);
    double peak = 0.0;
    const double worst = worst_over_scenes(card, eq, &peak);
    std::cout << "[ measured ] " << card.name << ": card vs exported law, largest stress difference " << worst
              << " MPa (peak " << peak << " MPa)\n";
    EXPECT_LT(worst, 1e-7 * peak) << card.name << ": " << worst << " MPa of " << peak;
  }
}

TEST(CardExportEquivalence, HillArmstrongFrederickIsMeasuredApproximation) {
  for (const char* name : {"aa3003o_c7_af_shell", "aa3003o_c5_af_brick"}) {
    const auto card = test::card(name);
    const auto eq = reports::exported_equivalent_card(card);
    double peak = 0.0;
    const double worst = worst_over_scenes(card, eq, &peak);
    std::cout << "[ measured ] " << name << ": Hill + AF vs exported Ziegler form, largest stress difference "
              << worst << " MPa (" << 100 * worst / peak << " % of " << peak << " MPa)\n";
    EXPECT_GT(worst, 1e-3 * peak);  // it is an approximation ...
    EXPECT_LT(worst, 0.15 * peak);  // ... and a near one (12.3 % for C.7, at 45 deg)
  }
}
