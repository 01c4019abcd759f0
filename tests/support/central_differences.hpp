#pragma once
// Exact derivatives along a path against central differences of whole paths with steps h and h/4
// (the direct differentiation tests): at every increment the largest difference to cd(h/4) must
// lie within the central differences' own spread |cd(h) - cd(h/4)| plus `floor` times the
// increment's largest |cd(h/4)|, taken no smaller than `scale_floor` (where the derivative
// vanishes, e.g. before friction acts, the round-off of the differences is all there is).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace spifit::test {

// Returns the largest difference over the increments, relative to each increment's scale.
template <class Vec>
double expect_within_central_differences(const std::vector<Vec>& exact, const std::vector<Vec>& cd, const std::vector<Vec>& cd4, double floor,
                                         const std::string& label, double scale_floor = 0.0) {
  double worst = 0.0;
  for (std::size_t n = 0; n < exact.size(); ++n) {
    const double scale = std::max(cd4[n].cwiseAbs().maxCoeff(), scale_floor);
    const double noise = (cd[n] - cd4[n]).cwiseAbs().maxCoeff();
    const double err = (exact[n] - cd4[n]).cwiseAbs().maxCoeff();
    worst = std::max(worst, err / scale);
    EXPECT_LE(err, noise + floor * scale) << label << ", increment " << n;
  }
  return worst;
}

}  // namespace spifit::test
