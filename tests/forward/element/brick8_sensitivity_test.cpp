// Direct differentiation through the one-point brick: the total derivative of its forces along a
// path of corner motions against central differences of whole paths with perturbed parameters
// (tests/support/hex_sensitivity_path.hpp). The path bends the element (an hourglass mode), so
// that the centre's state, the hourglass forces and the stabilisation built on the consistent
// tangent all carry history.
#include "forward/element/brick8.hpp"
#include "tests/support/hex_sensitivity_path.hpp"

#include <gtest/gtest.h>

namespace spifit::element {
namespace {

test::SolidFactory bricks(const HourglassOptions& o) {
  return [o](const SolidPoint::Law& law) { return std::make_unique<Brick8>(test::path_reference(), test::path_axes(), law, o); };
}

void expect_brick_path_derivatives_match(const HourglassOptions& o) {
  const std::unique_ptr<SolidElement> el = test::expect_path_derivatives_match(bricks(o));
  EXPECT_GT(static_cast<const Brick8&>(*el).hourglass_amplitudes().norm(), 1e-3);  // the bending carries the hourglass forces
}

TEST(Brick8Sensitivity, ForceDerivativesMatchCentralDifferencesAlongAPath) { expect_brick_path_derivatives_match(HourglassOptions{}); }

TEST(Brick8Sensitivity, WithAnElasticStabilisation) { expect_brick_path_derivatives_match(HourglassOptions{1.0, true}); }

TEST(Brick8Sensitivity, ThicknessRatioFollowsTheCorners) { test::expect_thickness_ratio_follows_the_corners(bricks(HourglassOptions{})); }

}  // namespace
}  // namespace spifit::element
