#pragma once
// What a Newton run reports: one IncrementReport per converged increment (passed to the
// increment callback) and the NewtonSummary of a solve.
#include "forward/solver/newton_counters.hpp"

#include <string>
#include <vector>

namespace spifit::solver {

struct IncrementReport {
  int index = 0;
  double lambda = 0.0, increment = 0.0;
  int iterations = 0;
  int line_searches = 0;
  bool extrapolated = false;  // started from the extrapolated predictor
  bool force_only = false;    // accepted on the force test alone at the minimum increment
  bool estimated = false;     // the displacement test passed on the estimated next correction
  // Stabilised increment: the damping factor c (0: none), the work of the viscous forces over the
  // increment (du . c |diag K| du) and their norm relative to the force scale of the convergence
  // test (the out-of-balance the accepted state carries).
  double damping = 0.0;
  double viscous_work = 0.0;
  double viscous_force = 0.0;
  std::vector<double> residual_norms;  // relative, one per iteration (first: before the first correction)
  std::vector<double> correction_norms;  // |alpha du| of each iteration (reduced unknowns)
};

struct NewtonSummary {
  bool converged = false;
  double lambda = 0.0;            // last converged load factor
  std::string message;            // why it stopped (failure: where and why)
  // Totals of the run (a resumed run's include its state's; factorisations and profile
  // seconds count over the solver's life).
  NewtonCounters counters;
  std::vector<IncrementReport> history;
};

}  // namespace spifit::solver
