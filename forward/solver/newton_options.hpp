#pragma once
// Options of the implicit Newton solver (NewtonSolver); docs/design/numerics-shell.md, "Global
// solution", explains the rules and records what they were measured to do.
#include "forward/solver/linear_solver.hpp"

#include <string>
#include <vector>

namespace spifit::solver {

struct NewtonOptions {
  // Increment sizes, as fractions of the load factor.
  double initial_increment = 0.1;
  double min_increment = 1e-5;      // a failure at this size ends the run (or starts stabilisation)
  double max_increment = 0.25;
  double growth = 1.5;              // size factor after an increment converged in <= easy_iterations
  int easy_iterations = 8;
  double cutback = 0.25;            // size factor after a failure (or the element's suggestion if smaller)
  int max_iterations = 20;          // per increment attempt
  double force_tolerance = 1e-7;    // |r| <= tol x force scale
  double displacement_tolerance = 1e-7;  // |correction| <= tol x |increment|
  // Energy line search (Crisfield): secant steps on s(alpha) = du . r(alpha), alpha in
  // [0.1, 1], at most max_line_search trials. Trials where an element fails are halved (up to
  // max_line_search times) whatever this says.
  bool line_search = false;
  int max_line_search = 6;
  // Predictor: the first iterate of an increment is the previous increment's free
  // displacement scaled to the new increment size, kept only when its residual is smaller
  // than that of the committed state.
  bool extrapolate = false;
  // An increment whose residual exceeds its initial one after `divergence_after` iterations
  // is cut back at once instead of iterating to max_iterations (0: never).
  int divergence_after = 3;
  // At the minimum increment (where a failure would end the run) the force test alone decides
  // and the divergence rule is off.
  bool force_only_at_minimum = true;
  // When the force test passes and the last correction fails the displacement test, the next
  // correction is estimated with the last factorisation (one back-substitution with the
  // previous iterate's tangent) and tested instead of iterating once more.
  bool estimate_next_correction = false;
  // Stabilised increments: when an increment fails at the minimum increment, where the run
  // would end, it is retried from the size that first failed with viscous forces c |diag K| du
  // (du: the increment's reduced displacement, |diag K| the tangent's diagonal at the committed
  // state; the tangent gains c |diag K| on its diagonal), and the increments that follow keep
  // them until `stabilised_increments` have converged. The accepted state carries the viscous
  // force as an out-of-balance; the dissipated work du . c |diag K| du is reported per increment
  // and in the summary. If a stabilised increment fails at the minimum increment too, c grows
  // x10 up to `max_stabilisation`. 0 (the default): off, the run ends there.
  double stabilisation = 0.0;
  double max_stabilisation = 0.0;  // 0: stabilisation x 100
  int stabilised_increments = 10;
  // Load factors that no increment steps over (finite, increasing): an increment reaching past
  // one, or ending less than 1e-3 of its size short of it, ends there instead, as at
  // lambda_end; the increment size is not reduced by this.
  std::vector<double> breakpoints{};
  // Load factors (finite, increasing) where increments end as at a breakpoint and after which
  // the increment size and the growth ceiling start afresh, as at the start of a solve: one
  // solve(l0, l_end) with restarts {l1, l2, ...} takes the increments of solve(l0, l1),
  // solve(l1, l2), ... one after the other. The stabilisation in force carries over (a new
  // solve would drop it).
  std::vector<double> restarts{};
  LinearSolverKind linear_solver = LinearSolverKind::automatic;
  // With linear_solver automatic: a tangent that is not symmetric (sliding friction) is
  // replaced by its symmetric part (K + K^T) / 2 and factorised with CHOLMOD instead of
  // factorising K with UMFPACK. The residual stays exact, so a converged increment is the same
  // to the tolerances; the iterations lose their quadratic rate in the friction terms. Where
  // CHOLMOD finds the symmetric part not positive definite, UMFPACK factorises the exact K.
  bool symmetric_tangent = false;
  // An iterate likely to end its increment (ConvergenceTest::likely_final) is assembled without
  // the tangent, which follows only if it does not end it. The iterates are the same either
  // way; false assembles every tangent (the comparison in the tests).
  bool skip_final_tangent = true;
  int element_chunk = 2048;    // elements evaluated in parallel before scattering
  // Linear analysis: one increment, one solve from the reference state, no equilibrium
  // iterations (patch tests and the linear benchmarks).
  bool linear = false;
  // Empty when valid, else the first problem.
  std::string validate() const;
};

}  // namespace spifit::solver
