#pragma once
// Where a long fit is (docs/guide/fitting.md, "Progress"): its iterations and the forward runs
// of each, with an estimate of what is left of the iteration from the run times measured so
// far. Ceres's iterations (and NLopt's evaluations) end an iteration; every FE run that ends
// (here, or on a worker rank) counts towards the iteration in progress. Library code never
// prints: the sink the caller gives does (the CLI's progress lines, the running summary).
#include <chrono>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

namespace spifit::inverse {

struct FitProgressEvent {
  enum class Kind { run, iteration };
  Kind kind = Kind::run;
  std::string phase;        // "" for the fit itself; "start 2 of 8", "r45 alone", ...
  int iteration = 0;        // the iteration in progress (run) or just ended (iteration); 0: the start point
  long runs = 0;            // FE forward runs of this iteration so far (retries included)
  long runs_expected = 0;   // FE runs an iteration with a central-difference Jacobian asks (0: no FE experiments)
  long runs_total = 0;      // FE forward runs since the fit started
  double cost = std::numeric_limits<double>::quiet_NaN();  // at the end of the iteration (iteration events)
  double elapsed = 0.0;     // seconds since the fit started
  double seconds_left = std::numeric_limits<double>::quiet_NaN();  // in this iteration, from the median run time (NaN: unknown)
  double median_run_seconds = std::numeric_limits<double>::quiet_NaN();
};
using FitProgressSink = std::function<void(const FitProgressEvent&)>;

class FitProgress {
 public:
  explicit FitProgress(FitProgressSink sink) : sink_(std::move(sink)), t0_(std::chrono::steady_clock::now()) {}

  // What an iteration asks: FE runs with a Jacobian (1 + 2p per FE scene file) and how many run
  // side by side (threads, or workers of an MPI job).
  void configure(long runs_per_iteration, int width);
  void set_runs_per_iteration(long runs);
  void set_phase(const std::string& phase);
  // A forward run ended after `seconds` (thread-safe).
  void run_finished(double seconds);
  // An iteration of the optimiser ended at `cost` (iteration 0: the start point).
  void iteration_finished(int iteration, double cost);
  // The state now (for a running summary).
  FitProgressEvent snapshot() const;

 private:
  FitProgressEvent event(FitProgressEvent::Kind kind) const;  // call with the mutex held
  FitProgressSink sink_;
  std::chrono::steady_clock::time_point t0_;
  mutable std::mutex mutex_;
  std::string phase_;
  long per_iteration_ = 0, runs_ = 0, total_ = 0;
  int width_ = 1, iteration_ = 0;
  double last_cost_ = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> run_seconds_;
};

}  // namespace spifit::inverse
