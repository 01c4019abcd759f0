#include "inverse/uncertainty/chi_square.hpp"

#include <cmath>
#include <limits>

namespace spifit::inverse {
namespace {

// Regularised upper incomplete gamma Q(a, x) = Γ(a, x) / Γ(a): below x = a + 1 from the series of
// the lower function P = 1 - Q, above it from the continued fraction of Q (modified Lentz), each
// where it converges fast.
double upper_incomplete_gamma(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
  constexpr double kEps = 1e-16;
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000 && std::abs(term) > kEps * std::abs(sum); ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return 1.0 - sum * std::exp(log_prefactor);
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int n = 1; n < 10000; ++n) {
    const double an = -n * (n - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEps) break;
  }
  return std::exp(log_prefactor) * h;
}

}  // namespace

double chi_square_upper_tail(int n, double x) { return upper_incomplete_gamma(0.5 * n, 0.5 * x); }

double chi_square_upper_quantile(int n, double tail) {
  if (n <= 0 || !(tail > 0.0 && tail < 1.0)) return std::numeric_limits<double>::quiet_NaN();
  // The tail falls as x grows: bracket, then bisect on the logarithm of the tail (it spans many
  // decades far out).
  double lo = 0.0, hi = n + 10.0;
  while (chi_square_upper_tail(n, hi) > tail) hi *= 2.0;
  const double target = std::log(tail);
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::log(chi_square_upper_tail(n, mid)) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace spifit::inverse
