#include "forward/element/thickness_rule.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace spifit::element {

ThicknessRule gauss_legendre_rule(int points) {
  if (points < kMinThicknessPoints || points > kMaxThicknessPoints)
    throw std::invalid_argument("unsupported number of thickness points " + std::to_string(points) + " (1 to 11)");
  ThicknessRule rule;
  const int n = points;
  rule.zeta.resize(static_cast<std::size_t>(n));
  rule.weight.resize(static_cast<std::size_t>(n));
  // Roots of P_n by Newton from the Chebyshev-like guess; P_n by the three-term recurrence.
  for (int i = 0; i < n; ++i) {
    double x = -std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 1 ? x : p1, pm = n == 1 ? 1.0 : p0;
      dp = n * (x * pn - pm) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule.zeta[static_cast<std::size_t>(i)] = x;
    rule.weight[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return rule;
}

}  // namespace spifit::element
