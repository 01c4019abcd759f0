#include "forward/solver/convergence_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spifit::solver {

ConvergenceTest::ConvergenceTest(const NewtonOptions& options, double external_force_norm, bool at_minimum)
    : options_(options), external_force_norm_(external_force_norm), at_minimum_(at_minimum) {}

double ConvergenceTest::initial(const Eigen::VectorXd& r, double reaction_norm) {
  initial_ = r.norm() / std::max({external_force_norm_, reaction_norm, r.norm(), 1e-300});
  return initial_;
}

double ConvergenceTest::relative(const Eigen::VectorXd& r, double reaction_norm) {
  force_scale_ = std::max({external_force_norm_, reaction_norm, 1e-300});
  return r.norm() / force_scale_;
}

Verdict ConvergenceTest::check_residual(double rel) const {
  return !std::isfinite(rel) || rel > 1e10 ? Verdict::diverged : Verdict::next_iteration;
}

Verdict ConvergenceTest::check(int iteration, double rel, double step, double increment_norm, const NextCorrection& next) const {
  const bool force = rel <= options_.force_tolerance;
  const double displacement = options_.displacement_tolerance * std::max(increment_norm, 1e-300);
  if (force && (step <= displacement || rel <= 1e-3 * options_.force_tolerance)) return Verdict::converged;
  // The last correction came from the previous, worse iterate: the next one, estimated with the
  // factorisation at hand (no assembly), decides instead of a further iteration.
  if (force && options_.estimate_next_correction) {
    double norm = 0.0;
    if (next(&norm) && norm <= displacement) return Verdict::estimated;
  }
  // At the minimum increment a failure ends the run: the force test alone decides there, and no
  // divergence cut-back is taken (there is nothing smaller to cut back to).
  if (at_minimum_ && force) return Verdict::force_only;
  if (!at_minimum_ && options_.divergence_after > 0 && iteration >= options_.divergence_after && rel > initial_)
    return Verdict::diverging;
  return Verdict::next_iteration;
}

bool ConvergenceTest::likely_final(double rel, double previous_rel, double step, double increment_norm) const {
  if (!(previous_rel > 0.0) || options_.linear) return false;
  const double rate = rel / previous_rel;
  if (!(rate < 1.0) || rel * rate > options_.force_tolerance) return false;
  const double displacement = options_.displacement_tolerance * increment_norm;
  return step <= displacement || (options_.estimate_next_correction && step * rate <= displacement);
}

std::string ConvergenceTest::failure_reason(Verdict v, int iteration, double rel) const {
  char buf[160];
  switch (v) {
    case Verdict::diverged: return "Newton iterations diverged (relative residual " + std::to_string(rel) + ")";
    case Verdict::diverging:
      std::snprintf(buf, sizeof buf, "Newton iterations diverging (relative residual %.3g after %d iterations, %.3g at the start)", rel,
                    iteration, initial_);
      return buf;
    default:
      std::snprintf(buf, sizeof buf, "no convergence in %d iterations (relative residual %.3g)", options_.max_iterations, rel);
      return buf;
  }
}

}  // namespace spifit::solver
