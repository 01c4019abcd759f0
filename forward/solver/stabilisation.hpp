#pragma once
// Stabilised increments (docs/design/numerics-shell.md, "Stabilised increments"; NewtonOptions::
// stabilisation): viscous forces c D du_bar on the reduced unknowns of an increment, and the
// damping factor c that an increment failing at the minimum increment switches on or raises.
#include "forward/solver/newton_counters.hpp"
#include "forward/solver/newton_options.hpp"
#include "forward/solver/newton_report.hpp"
#include "forward/solver/sparse_matrix.hpp"

#include <Eigen/Core>

namespace spifit::solver {

// The viscous forces of one increment: c D du_bar with D = |diag K| of the tangent at the
// committed state (fixed for the increment) and du_bar the sum of the accepted corrections (the
// increment's reduced displacement; the prescribed part is not a reduced unknown). The
// residual with them is r + c D du_bar, its tangent K + c D. Inactive (every call a no-op) when
// the damping factor is 0.
class ViscousForces {
 public:
  // k: the tangent assembled at the committed state; n: the number of reduced unknowns.
  ViscousForces(double damping, const SparseMatrix& k, Eigen::Index n);
  bool active() const { return damping_ > 0.0; }
  void add_to_tangent(SparseMatrix* k) const;
  // The residual of the trial iterate + alpha du gains c D (du_bar + alpha du).
  void add_to_residual(Eigen::VectorXd* r, const Eigen::VectorXd& du, double alpha) const;
  void accept(const Eigen::VectorXd& du, double alpha);  // du_bar += alpha du
  // The damping factor, the viscous work du_bar . c D du_bar and the norm of c D du_bar over
  // force_scale, into the report of the accepted increment.
  void report(double force_scale, IncrementReport* report) const;

 private:
  double damping_;
  Eigen::VectorXd viscosity_, du_bar_;  // c D and du_bar (empty when inactive)
};

// The damping factor in force across increments.
class Stabilisation {
 public:
  explicit Stabilisation(const NewtonOptions& options);
  double damping() const { return damping_; }  // for the next increment (0: none)
  int increments_left() const { return left_; }
  void reset() { restore(0.0, 0); }
  void restore(double damping, int increments_left);
  // A converged increment: a stabilised one adds to the totals and uses up one of the
  // increments the damping lasts.
  void converged(const IncrementReport& report, NewtonCounters* counters);
  // An increment failed at the minimum increment: switches the damping on, or raises it x10 up
  // to max_stabilisation, for the next stabilised_increments converged increments. false when
  // stabilisation is off or the damping is already at its largest (the run ends).
  bool escalate();

 private:
  const NewtonOptions& options_;
  double max_damping_;
  double damping_ = 0.0;
  int left_ = 0;
};

}  // namespace spifit::solver
