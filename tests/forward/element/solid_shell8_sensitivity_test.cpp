// Direct differentiation through the solid-shell: the total derivative of its forces along a
// path of corner motions against central differences of whole paths with perturbed parameters
// (tests/support/hex_sensitivity_path.hpp). The path bends the element, so that the enhanced
// thickness strains and the levels' mean dilatation carry the derivatives through the
// condensation; the back-stress makes the tangent's blocks non-symmetric.
#include "forward/element/solid_shell8.hpp"
#include "tests/support/hex_sensitivity_path.hpp"

#include <gtest/gtest.h>

namespace spifit::element {
namespace {

// The enhanced strains converged to 1e-13: at the element's default 1e-8 the committed points'
// states carry errors of that order, and central differences of Swift's n (h = 1e-4) lay up to
// 1.2e-5 of the largest derivative from the exact derivatives (1.5e-7 to 1e-6 for K, C_X).
test::SolidFactory solid_shells() {
  return [](const SolidPoint::Law& law) {
    return std::make_unique<SolidShell8>(test::path_reference(), test::path_axes(), law, gauss_legendre_rule(3), 1e-13);
  };
}

TEST(SolidShell8Sensitivity, ForceDerivativesMatchCentralDifferencesAlongAPath) {
  // Half the bricks' strains, in two increments per stage: on the bricks' path the enhanced
  // strains' Newton iteration fails near its full load (at a quarter of a stage per increment too).
  const std::unique_ptr<SolidElement> el = test::expect_path_derivatives_match(solid_shells(), 2, 0.5);
  EXPECT_GT(static_cast<const SolidShell8&>(*el).enhanced().norm(), 1e-4);  // the enhanced strains take part
}

TEST(SolidShell8Sensitivity, ThicknessRatioFollowsTheCorners) { test::expect_thickness_ratio_follows_the_corners(solid_shells()); }

}  // namespace
}  // namespace spifit::element
