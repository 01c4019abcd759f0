#pragma once
// The progress line of a long run on stderr without --verbose: the fraction of the tool path,
// the time so far and an estimate of the time left. Silent for the first few seconds (short
// runs print nothing). On a terminal the line is rewritten in place at most every half
// second; elsewhere (a log file, a batch job) a new line every `log_every` seconds.
#include <optional>
#include <string>

namespace spifit::cli {

class ProgressMeter {
 public:
  ProgressMeter(bool terminal, double log_every = 30.0, double quiet_for = 3.0)
      : terminal_(terminal), log_every_(log_every), quiet_for_(quiet_for) {}

  // The text to print now (with its leading "\r" on a terminal, its newline elsewhere), or
  // nothing, after `elapsed` seconds with `fraction` of the path done.
  std::optional<std::string> update(double fraction, double elapsed);
  // What ends the progress output when the run ends ("\n" after a terminal line), or nothing.
  std::optional<std::string> finish() const;

  // "12.5 % of the tool path, 1:02 elapsed, about 7:14 left" (no estimate before 1 % or 2 s).
  static std::string line(double fraction, double elapsed);

 private:
  bool terminal_;
  double log_every_, quiet_for_;
  double last_ = -1e300;
  bool printed_ = false;
};

}  // namespace spifit::cli
