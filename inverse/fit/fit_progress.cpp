#include "inverse/fit/fit_progress.hpp"

#include <algorithm>
#include <cmath>

namespace spifit::inverse {

void FitProgress::configure(long runs_per_iteration, int width) {
  std::lock_guard<std::mutex> lock(mutex_);
  per_iteration_ = runs_per_iteration;
  width_ = std::max(1, width);
}

void FitProgress::set_runs_per_iteration(long runs) {
  std::lock_guard<std::mutex> lock(mutex_);
  per_iteration_ = runs;
}

void FitProgress::set_phase(const std::string& phase) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (phase == phase_) return;
  phase_ = phase;
  iteration_ = 0;
  runs_ = 0;
}

FitProgressEvent FitProgress::event(FitProgressEvent::Kind kind) const {
  FitProgressEvent e;
  e.kind = kind;
  e.phase = phase_;
  e.iteration = iteration_;
  e.runs = runs_;
  e.runs_expected = per_iteration_;
  e.runs_total = total_;
  e.cost = last_cost_;
  e.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  if (!run_seconds_.empty()) {
    std::vector<double> s = run_seconds_;
    const std::size_t n = s.size();
    std::nth_element(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(n / 2), s.end());
    e.median_run_seconds = s[n / 2];
    // The runs still to come in this iteration, side by side in batches of the width.
    if (per_iteration_ > 0) {
      const long left = std::max(0L, per_iteration_ - runs_);
      e.seconds_left = std::ceil(static_cast<double>(left) / width_) * e.median_run_seconds;
    }
  }
  return e;
}

// The sink is called with the mutex held, so that the events reach it in the order they
// happened (a run's line never after the end of its iteration); it must not call back.
void FitProgress::run_finished(double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++runs_;
  ++total_;
  run_seconds_.push_back(seconds);
  if (sink_) sink_(event(FitProgressEvent::Kind::run));
}

void FitProgress::iteration_finished(int iteration, double cost) {
  std::lock_guard<std::mutex> lock(mutex_);
  iteration_ = iteration;
  last_cost_ = cost;
  if (sink_) sink_(event(FitProgressEvent::Kind::iteration));
  iteration_ = iteration + 1;  // the runs from now on belong to the next one
  runs_ = 0;
}

FitProgressEvent FitProgress::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return event(FitProgressEvent::Kind::run);
}

}  // namespace spifit::inverse
