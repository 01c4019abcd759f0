#include "cli/fit_progress_lines.hpp"

#include "cli/progress_meter.hpp"

#include <cmath>
#include <cstdio>

namespace spifit::cli {
namespace {

std::string prefix(const inverse::FitProgressEvent& e) {
  return (e.phase.empty() ? "" : e.phase + ": ") + "iteration " + std::to_string(e.iteration);
}

std::string runs_of(long runs, long expected) {
  return std::to_string(runs) + (expected > 0 && runs <= expected ? " of " + std::to_string(expected) : "");
}

}  // namespace

std::string FitProgressLines::iteration_line(const inverse::FitProgressEvent& e) {
  char cost[64];
  std::snprintf(cost, sizeof cost, "%.6g", e.cost);
  std::string s = prefix(e) + ": cost " + cost;
  if (e.runs_total > 0) s += ", " + std::to_string(e.runs) + " FE runs (" + std::to_string(e.runs_total) + " in all)";
  return s + ", " + clock_time(e.elapsed) + " elapsed";
}

std::string FitProgressLines::run_line(const inverse::FitProgressEvent& e) {
  std::string s = prefix(e) + ": FE run " + runs_of(e.runs, e.runs_expected) + ", " + clock_time(e.elapsed) + " elapsed";
  if (std::isfinite(e.seconds_left) && e.runs < e.runs_expected) s += ", about " + clock_time(e.seconds_left) + " left in this iteration";
  return s;
}

std::optional<std::string> FitProgressLines::update(const inverse::FitProgressEvent& e) {
  using Kind = inverse::FitProgressEvent::Kind;
  const bool fe = e.runs_total > 0;
  if (!fe && e.elapsed < quiet_for_) return std::nullopt;
  if (e.kind == Kind::iteration) {
    // Without FE runs an iteration takes milliseconds (an NLopt iteration is one evaluation):
    // a line at most every half second on a terminal, every log_every seconds in a log.
    if (!fe) {
      if (e.elapsed - last_iteration_line_ < (terminal_ ? 0.5 : log_every_)) return std::nullopt;
      last_iteration_line_ = e.elapsed;
    }
    const std::string text = "spifit: " + iteration_line(e);
    open_line_ = false;
    last_run_line_ = -1e300;
    return terminal_ ? "\r" + text + "\033[K\n" : text + "\n";
  }
  const double every = terminal_ ? 0.5 : log_every_;
  if (e.elapsed - last_run_line_ < every) return std::nullopt;
  last_run_line_ = e.elapsed;
  const std::string text = "spifit: " + run_line(e);
  if (!terminal_) return text + "\n";
  open_line_ = true;
  return "\r" + text + "\033[K";
}

std::optional<std::string> FitProgressLines::finish() const {
  if (terminal_ && open_line_) return std::string("\n");
  return std::nullopt;
}

nlohmann::json fit_progress_json(const inverse::FitProgressEvent& e) {
  nlohmann::json j{{"forward_runs", e.runs_total}, {"iteration", e.iteration}, {"elapsed", e.elapsed}};
  if (!e.phase.empty()) j["phase"] = e.phase;
  if (e.runs_expected > 0) {
    j["iteration_runs"] = e.runs;
    j["iteration_runs_expected"] = e.runs_expected;
  }
  if (std::isfinite(e.cost)) j["cost"] = e.cost;
  if (std::isfinite(e.seconds_left)) j["iteration_seconds_left"] = e.seconds_left;
  if (std::isfinite(e.median_run_seconds)) j["median_run_seconds"] = e.median_run_seconds;
  return j;
}

}  // namespace spifit::cli
