#pragma once
// The progress line of a long run on stderr without --verbose: the fraction of the tool path,
// the time so far and an estimate of the time left. Silent for the first few seconds (short
// runs print nothing). On a terminal the line is rewritten in place at most every half
// second; elsewhere (a log file, a batch job) a new line every `log_every` seconds.
#include <deque>
#include <optional>
#include <string>
#include <utility>

namespace spifit::cli {

// The time left of a run from its measured progress: the rate of the recent past, over the last
// third of the time since the first increment (at least kMinWindow seconds), so that neither
// the set-up before the first increment nor a slow start (the tool's first contact) weighs on
// the estimate once the run has settled (docs/design/decisions.md, "Estimated time left").
class RemainingTime {
 public:
  static constexpr double kMinWindow = 5.0;
  // The run has done `fraction` of its path after `elapsed` seconds.
  void add(double fraction, double elapsed);
  // Seconds left; nothing before 1 % of the path or 2 s after the first increment.
  std::optional<double> seconds() const;

 private:
  std::deque<std::pair<double, double>> samples_;  // (elapsed, fraction), oldest first, the window's
  double first_ = -1.0;                            // elapsed at the first increment
};

// "m:ss", or "h:mm:ss" from an hour.
std::string clock_time(double seconds);

class ProgressMeter {
 public:
  ProgressMeter(bool terminal, double log_every = 30.0, double quiet_for = 3.0)
      : terminal_(terminal), log_every_(log_every), quiet_for_(quiet_for) {}

  // The text to print now (with its leading "\r" on a terminal, its newline elsewhere), or
  // nothing, after `elapsed` seconds with `fraction` of the path done; the time left goes by
  // `load` (ProgressEvent::load: the path with the moves through the air shortened), by the
  // fraction without it.
  std::optional<std::string> update(double fraction, double elapsed, std::optional<double> load = std::nullopt);
  // What ends the progress output when the run ends ("\n" after a terminal line), or nothing.
  std::optional<std::string> finish() const;

  // "12.5 % of the tool path, 1:02 elapsed, about 7:14 left" (the estimate when there is one).
  static std::string line(double fraction, double elapsed, std::optional<double> seconds_left);

 private:
  bool terminal_;
  double log_every_, quiet_for_;
  double last_ = -1e300;
  bool printed_ = false;
  RemainingTime left_;
};

}  // namespace spifit::cli
