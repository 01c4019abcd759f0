#include "forward/scenes/common/force_ripple.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace spifit::scene {

namespace {

constexpr int kMinSamples = 7;
constexpr double kMaxTurn = std::numbers::pi / 4.0;

// Whether samples [lo, hi] are steady travel: one height, an in-plane turn of at most kMaxTurn.
bool steady(const std::vector<ToolForceSample>& s, std::size_t lo, std::size_t hi) {
  double first = 0.0;
  bool have = false;
  for (std::size_t i = lo; i < hi; ++i) {
    const Eigen::Vector3d d = s[i + 1].centre - s[i].centre;
    if (std::abs(d.z()) > 1e-9 || std::abs(s[i + 1].centre.z() - s[lo].centre.z()) > 1e-9) return false;
    if (d.head<2>().squaredNorm() == 0.0) continue;
    const double a = std::atan2(d.y(), d.x());
    if (!have) {
      first = a;
      have = true;
    } else if (std::abs(std::remainder(a - first, 2.0 * std::numbers::pi)) > kMaxTurn) {
      return false;
    }
  }
  return have;
}

// The mean of component k over the travel [a, b], the force linear between samples; samples
// [lo, hi] bracket the interval (travel(lo) <= a, travel(hi) >= b).
double window_mean(const std::vector<ToolForceSample>& s, std::size_t lo, std::size_t hi, double a, double b, int k) {
  double sum = 0.0;
  for (std::size_t i = lo; i < hi; ++i) {
    const double t0 = s[i].travel, t1 = s[i + 1].travel;
    const double u = std::max(a, t0), v = std::min(b, t1);
    if (!(v > u)) continue;
    const auto at = [&](double t) { return s[i].force(k) + (s[i + 1].force(k) - s[i].force(k)) * (t - t0) / (t1 - t0); };
    sum += 0.5 * (at(u) + at(v)) * (v - u);
  }
  return sum / (b - a);
}

}  // namespace

ForceRipple force_ripple(const std::vector<ToolForceSample>& s, double window) {
  ForceRipple r;
  r.window = window;
  double peak = 0.0;
  for (const auto& x : s) peak = std::max(peak, x.force.norm());
  if (!(peak > 0.0) || !(window > 0.0) || s.empty()) return r;
  const double half = 0.5 * window, slack = 1e-9 * (1.0 + window);
  std::size_t lo = 0, hi = 0;  // the samples bracketing the window of sample i
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = s[i].travel, a = t - half, b = t + half;
    if (a < s.front().travel - slack || b > s.back().travel + slack) continue;
    while (lo + 1 < s.size() && s[lo + 1].travel <= a + slack) ++lo;
    hi = std::max(hi, i);
    while (hi < s.size() - 1 && s[hi].travel < b - slack) ++hi;
    // The tool also arrives at sample lo along the window's direction: a window that starts at a
    // corner or at the foot of a plunge is not steady.
    if (hi - lo + 1 < kMinSamples || !steady(s, lo > 0 ? lo - 1 : lo, hi)) continue;
    ++r.windows;
    for (int k = 0; k < 3; ++k) {
      const double dev = std::abs(s[i].force(k) - window_mean(s, lo, hi, a, b, k)) / peak;
      if (dev > r.amplitude) {
        r.amplitude = dev;
        r.travel = t;
        r.component = k;
      }
    }
  }
  return r;
}

std::string ripple_warning(const ForceRipple& r) {
  if (!(r.amplitude > kRippleWarningFraction)) return {};
  char buf[400];
  std::snprintf(buf, sizeof buf, "the tool force ripples: F%c departs from its mean over one element length (%.3g mm) by up to %.0f %% "
                "of the peak force (at %.4g mm of travel); the elements are coarse for the tool: refine the mesh along the track, "
                "or compare forces averaged over an element length", "xyz"[r.component], r.window, 100.0 * r.amplitude, r.travel);
  return buf;
}

}  // namespace spifit::scene
