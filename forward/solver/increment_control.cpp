#include "forward/solver/increment_control.hpp"

#include <algorithm>

namespace spifit::solver {

double IncrementControl::segment_end(double lambda, double lambda_end) const {
  const auto& rs = options_.restarts;
  const auto next = std::upper_bound(rs.begin(), rs.end(), lambda + 1e-12);
  return next != rs.end() && *next < lambda_end ? *next : lambda_end;
}

double IncrementControl::first_size(double lambda, double lambda_end) const {
  return options_.linear ? segment_end(lambda, lambda_end) - lambda : options_.initial_increment;
}

void IncrementControl::start(double lambda_start, double lambda_end) {
  lambda_ = lambda_start;
  size_ = first_size(lambda_start, lambda_end);
  ceiling_ = options_.max_increment;
}

void IncrementControl::restore(double lambda, double size, double ceiling) {
  lambda_ = lambda;
  size_ = size;
  ceiling_ = ceiling;
}

double IncrementControl::next_end(double lambda_end) const {
  // A restart ends the increment as lambda_end does: the increments of a segment are those of a
  // solve that ends there.
  const double end = segment_end(lambda_, lambda_end);
  double lambda1 = std::min(lambda_ + size_, end);
  if (end - lambda1 < 1e-3 * size_) lambda1 = end;
  // The next breakpoint after lambda: the increment ends there (also when it would end just short of it).
  const auto& bp = options_.breakpoints;
  const auto next = std::upper_bound(bp.begin(), bp.end(), lambda_ + 1e-12);
  if (next != bp.end() && *next < end && *next - lambda1 < 1e-3 * size_) lambda1 = *next;
  return lambda1;
}

void IncrementControl::converged(double lambda1, int iterations, double lambda_end) {
  first_failed_ = 0.0;
  lambda_ = lambda1;
  // Growth stays below a size that failed recently; that ceiling relaxes slowly.
  ceiling_ = std::min(options_.max_increment, ceiling_ * 1.1);
  if (iterations <= options_.easy_iterations) size_ = std::min(ceiling_, size_ * options_.growth);
  // next_end ends an increment on a restart point exactly at its value.
  if (std::binary_search(options_.restarts.begin(), options_.restarts.end(), lambda1)) start(lambda1, lambda_end);
}

void IncrementControl::failed(double lambda1) {
  ceiling_ = std::max(options_.min_increment, 0.75 * (lambda1 - lambda_));
  if (first_failed_ == 0.0) first_failed_ = lambda1 - lambda_;
}

void IncrementControl::cut_back(double suggested_scale) {
  size_ = std::max(options_.min_increment, size_ * std::min(options_.cutback, suggested_scale));
}

void IncrementControl::retry_first_failed() {
  size_ = std::max(options_.min_increment, first_failed_);
  ceiling_ = std::max(ceiling_, size_);
  first_failed_ = 0.0;
}

}  // namespace spifit::solver
