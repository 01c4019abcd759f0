#include "cli/progress_meter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spifit::cli {

namespace {

// "m:ss", or "h:mm:ss" from an hour.
std::string clock_time(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

}  // namespace

std::string ProgressMeter::line(double fraction, double elapsed) {
  const double f = std::clamp(fraction, 0.0, 1.0);
  char buf[120];
  std::snprintf(buf, sizeof buf, "%.1f %% of the tool path, %s elapsed", 100.0 * f, clock_time(elapsed).c_str());
  std::string out = buf;
  if (f >= 0.01 && elapsed >= 2.0 && f < 1.0) out += ", about " + clock_time(elapsed * (1.0 - f) / f) + " left";
  return out;
}

std::optional<std::string> ProgressMeter::update(double fraction, double elapsed) {
  if (elapsed < quiet_for_) return std::nullopt;
  const double every = terminal_ ? 0.5 : log_every_;
  if (printed_ && elapsed - last_ < every) return std::nullopt;
  last_ = elapsed;
  printed_ = true;
  return terminal_ ? "\rspifit: " + line(fraction, elapsed) + "\033[K" : "spifit: " + line(fraction, elapsed) + "\n";
}

std::optional<std::string> ProgressMeter::finish() const {
  if (terminal_ && printed_) return std::string("\n");
  return std::nullopt;
}

}  // namespace spifit::cli
