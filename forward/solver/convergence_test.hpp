#pragma once
// The convergence test of one Newton increment (docs/design/numerics-shell.md, "Global solution",
// Convergence): the force scale and relative residual of an iterate, the rules that accept it,
// and the rules that give the increment up.
#include "forward/solver/newton_options.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>

namespace spifit::solver {

enum class Verdict {
  converged,       // force test and displacement test (or a residual 1000x below the force tolerance)
  estimated,       // force test, and the displacement test on the estimated next correction
  force_only,      // force test alone, at the minimum increment
  next_iteration,  // none of the rules decides yet
  diverging,       // residual above the increment's initial one after divergence_after iterations
  diverged,        // residual non-finite or above 1e10 times the force scale
};

class ConvergenceTest {
 public:
  // external_force_norm: |f_ext| of the increment's end (reduced); at_minimum: the increment
  // has the minimum size and force_only_at_minimum is on.
  ConvergenceTest(const NewtonOptions& options, double external_force_norm, bool at_minimum);

  // Relative residual of the increment's first iterate, whose force scale includes |r| itself
  // (where external forces and reactions may both still vanish). Kept for the divergence rule.
  double initial(const Eigen::VectorXd& r, double reaction_norm);
  // Relative residual of an iterate after a correction; its force scale, max(|f_ext|,
  // |reactions|), is kept for force_scale().
  double relative(const Eigen::VectorXd& r, double reaction_norm);
  double force_scale() const { return force_scale_; }

  // diverged or next_iteration.
  Verdict check_residual(double rel) const;
  // Norm of the next Newton correction estimated with the last factorisation; false when there
  // is none. Called only when the rule needs it.
  using NextCorrection = std::function<bool(double* norm)>;
  // After iteration `iteration` with relative residual rel, correction norm `step` and the
  // increment's norm from the committed state `increment_norm`: the accept rules in order
  // (converged, estimated, force_only), then the divergence rule.
  Verdict check(int iteration, double rel, double step, double increment_norm, const NextCorrection& next) const;

  // Whether the iterate that a correction of norm `step` leads to will likely be accepted: its
  // residual extrapolated at the last rate (rel x rel / previous_rel; previous_rel <= 0: none
  // yet) passes the force test, and the correction (or, with estimate_next_correction, the next
  // one extrapolated at the same rate) the displacement test against increment_norm, a lower
  // bound of the increment's norm there. Conservative for quadratic convergence; the solver
  // then assembles that iterate's residual without the tangent (NewtonSolver::increment).
  bool likely_final(double rel, double previous_rel, double step, double increment_norm) const;

  // Why the increment failed: diverged, diverging, or (next_iteration) no convergence within
  // max_iterations.
  std::string failure_reason(Verdict v, int iteration, double rel) const;

 private:
  const NewtonOptions& options_;
  double external_force_norm_;
  bool at_minimum_;
  double initial_ = 0.0;
  double force_scale_ = 1e-300;
};

}  // namespace spifit::solver
