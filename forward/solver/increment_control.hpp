#pragma once
// Automatic increment control (docs/design/numerics-shell.md, "Global solution", Increment control):
// where the next increment ends (lambda_end, breakpoints, restarts), growth after easy
// increments under a ceiling that a failure lowers, cut-back after a failure, and the minimum
// increment where a failure ends the run.
#include "forward/solver/newton_options.hpp"

namespace spifit::solver {

class IncrementControl {
 public:
  explicit IncrementControl(const NewtonOptions& options) : options_(options) {}

  double lambda() const { return lambda_; }     // committed load factor
  double size() const { return size_; }         // size of the next increment to try
  double ceiling() const { return ceiling_; }   // growth ceiling
  bool started() const { return size_ > 0.0 && ceiling_ > 0.0; }
  bool reached(double lambda_end) const { return !(lambda_ < lambda_end - 1e-12); }
  bool at_minimum() const { return size_ <= options_.min_increment * (1.0 + 1e-12); }

  // From lambda_start to lambda_end: the size and the ceiling start afresh.
  void start(double lambda_start, double lambda_end);
  // A stepping state (checkpoint).
  void restore(double lambda, double size, double ceiling);
  // At the start of a run (solve or resume): no failed attempt yet.
  void begin_run() { first_failed_ = 0.0; }

  // Where the increment from the committed load factor ends: lambda + size, or the end of the
  // segment (lambda_end or the next restart) or the next breakpoint when it would reach past it
  // or end less than 1e-3 of its size short of it.
  double next_end(double lambda_end) const;
  // A converged increment to lambda1 in `iterations` iterations: it is committed; the ceiling
  // relaxes by 10 %, the size grows after an easy increment, and both start afresh after a
  // restart point.
  void converged(double lambda1, int iterations, double lambda_end);
  // A failed attempt to lambda1: the ceiling drops below its size.
  void failed(double lambda1);
  // After a failure above the minimum size: the size x min(cutback, suggested_scale).
  void cut_back(double suggested_scale);
  // After a failure at the minimum size that switched stabilisation on: the size that first
  // failed since the last converged increment is tried again.
  void retry_first_failed();

 private:
  const NewtonOptions& options_;
  double lambda_ = 0.0, size_ = 0.0, ceiling_ = 0.0;
  double first_failed_ = 0.0;  // size of the first failed attempt since the last converged increment
  // lambda_end, or the first restart after lambda before it.
  double segment_end(double lambda, double lambda_end) const;
  // The size an increment from lambda starts with (linear: the whole segment).
  double first_size(double lambda, double lambda_end) const;
};

}  // namespace spifit::solver
