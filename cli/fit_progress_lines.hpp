#pragma once
// The progress lines of a fit on stderr without --quiet (docs/guide/fitting.md, "Progress"):
// one line per iteration (its cost, its FE runs, the time so far) and, while an iteration's FE
// runs go on, where it is among them with the time left of it from the measured run times. On
// a terminal the run line is rewritten in place (at most every half second) and each iteration
// line stays; in a log a run line at most every `log_every` seconds. A fit of material points
// only prints once it has taken `quiet_for` seconds (most end before), and then an iteration line
// at most every half second (terminal) or `log_every` seconds (log).
#include "inverse/fit/fit_progress.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace spifit::cli {

class FitProgressLines {
 public:
  FitProgressLines(bool terminal, double log_every = 30.0, double quiet_for = 2.0)
      : terminal_(terminal), log_every_(log_every), quiet_for_(quiet_for) {}

  // What to print for this event, or nothing.
  std::optional<std::string> update(const inverse::FitProgressEvent& e);
  // What ends the output when the fit ends ("\n" after a run line left on a terminal), or nothing.
  std::optional<std::string> finish() const;

  // "iteration 3: cost 12.5, 11 FE runs (34 in all), 1:02 elapsed"
  static std::string iteration_line(const inverse::FitProgressEvent& e);
  // "iteration 3: FE run 5 of 11, 1:02 elapsed, about 0:40 left in this iteration"
  static std::string run_line(const inverse::FitProgressEvent& e);

 private:
  bool terminal_;
  double log_every_, quiet_for_;
  double last_run_line_ = -1e300, last_iteration_line_ = -1e300;
  bool open_line_ = false;  // a run line on the terminal, not yet ended
};

// The running summary's "progress" of a fit (what `spifit status` shows).
nlohmann::json fit_progress_json(const inverse::FitProgressEvent& e);

}  // namespace spifit::cli
