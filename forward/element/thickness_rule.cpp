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

namespace {

// Gauss-Lobatto points on [-1, 1]: the ends and the roots of P'_{m-1}; weights
// 2 / (m (m - 1) P_{m-1}(x)^2).
void gauss_lobatto(int m, std::vector<double>* x, std::vector<double>* w) {
  const auto legendre = [](int n, double t, double* previous) {
    double p0 = 1.0, p1 = t;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    *previous = p0;
    return n == 0 ? 1.0 : p1;
  };
  const int n = m - 1;
  x->assign(static_cast<std::size_t>(m), 0.0);
  w->assign(static_cast<std::size_t>(m), 0.0);
  (*x)[0] = -1.0;
  (*x)[static_cast<std::size_t>(n)] = 1.0;
  for (int i = 1; i < n; ++i) {
    double t = -std::cos(std::numbers::pi * i / n);
    for (int it = 0; it < 100; ++it) {
      double pm = 0.0;
      const double pn = legendre(n, t, &pm);
      const double d1 = n * (t * pn - pm) / (t * t - 1.0);            // P_n'
      const double d2 = (2.0 * t * d1 - n * (n + 1.0) * pn) / (1.0 - t * t);  // Legendre's equation
      const double dt = d1 / d2;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    (*x)[static_cast<std::size_t>(i)] = t;
  }
  for (int i = 0; i < m; ++i) {
    double pm = 0.0;
    const double pn = legendre(n, (*x)[static_cast<std::size_t>(i)], &pm);
    (*w)[static_cast<std::size_t>(i)] = 2.0 / (m * (m - 1.0) * pn * pn);
  }
}

}  // namespace

bool thickness_rule_from_string(const std::string& s, ThicknessRuleKind* kind) {
  if (s == "gauss") { *kind = ThicknessRuleKind::gauss; return true; }
  if (s == "surface") { *kind = ThicknessRuleKind::surface; return true; }
  return false;
}

const char* to_string(ThicknessRuleKind kind) { return kind == ThicknessRuleKind::gauss ? "gauss" : "surface"; }

ThicknessRule make_thickness_rule(ThicknessRuleKind kind, int points) {
  if (kind == ThicknessRuleKind::gauss) return gauss_legendre_rule(points);
  if (points < 3 || points > kMaxThicknessPoints || points % 2 == 0)
    throw std::invalid_argument("unsupported number of thickness points " + std::to_string(points) +
                                " for the surface rule (odd, 3 to 11)");
  const int m = (points + 1) / 2;  // Lobatto points per half, the mid-surface shared
  std::vector<double> x, w;
  gauss_lobatto(m, &x, &w);
  ThicknessRule rule;
  for (int half = 0; half < 2; ++half)
    for (int i = 0; i < m; ++i) {
      const double z = 0.5 * (x[static_cast<std::size_t>(i)] + (half == 0 ? -1.0 : 1.0));
      const double wz = 0.5 * w[static_cast<std::size_t>(i)];
      if (half == 1 && i == 0) {
        rule.weight.back() += wz;  // the shared mid-surface point
        continue;
      }
      rule.zeta.push_back(z);
      rule.weight.push_back(wz);
    }
  return rule;
}

}  // namespace spifit::element
