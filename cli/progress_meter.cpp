#include "cli/progress_meter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spifit::cli {

std::string clock_time(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

void RemainingTime::add(double fraction, double elapsed) {
  if (first_ < 0.0) first_ = elapsed;
  samples_.emplace_back(elapsed, fraction);
  // The window's start only moves forward: what falls out of it never comes back.
  const double window = std::max(kMinWindow, (elapsed - first_) / 3.0);
  while (samples_.size() > 2 && samples_[1].first <= elapsed - window) samples_.pop_front();
}

std::optional<double> RemainingTime::seconds() const {
  if (samples_.size() < 2) return std::nullopt;
  const auto& [t1, f1] = samples_.back();
  const auto& [t0, f0] = samples_.front();
  if (f1 < 0.01 || f1 >= 1.0 || t1 - first_ < 2.0 || !(t1 > t0) || !(f1 > f0)) return std::nullopt;
  return (1.0 - f1) * (t1 - t0) / (f1 - f0);
}

std::string ProgressMeter::line(double fraction, double elapsed, std::optional<double> seconds_left) {
  const double f = std::clamp(fraction, 0.0, 1.0);
  char buf[120];
  std::snprintf(buf, sizeof buf, "%.1f %% of the tool path, %s elapsed", 100.0 * f, clock_time(elapsed).c_str());
  std::string out = buf;
  if (seconds_left && f < 1.0) out += ", about " + clock_time(*seconds_left) + " left";
  return out;
}

std::optional<std::string> ProgressMeter::update(double fraction, double elapsed, std::optional<double> load) {
  left_.add(load ? *load : fraction, elapsed);
  if (elapsed < quiet_for_) return std::nullopt;
  const double every = terminal_ ? 0.5 : log_every_;
  if (printed_ && elapsed - last_ < every) return std::nullopt;
  last_ = elapsed;
  printed_ = true;
  const std::string text = line(fraction, elapsed, left_.seconds());
  return terminal_ ? "\rspifit: " + text + "\033[K" : "spifit: " + text + "\n";
}

std::optional<std::string> ProgressMeter::finish() const {
  if (terminal_ && printed_) return std::string("\n");
  return std::nullopt;
}

}  // namespace spifit::cli
