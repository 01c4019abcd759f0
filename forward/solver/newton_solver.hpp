#pragma once
// Implicit static solution (NUMERICS.md "Global solution"): load factor lambda from 0 to 1 in
// increments; Newton-Raphson on the reduced residual with a line search; automatic
// increment control (cut back on divergence or material failure, grow after easy increments);
// parallel element evaluation (OpenMP) with assembly in element order, so results do not
// depend on the thread count; UMFPACK or CHOLMOD on a pattern built once (symbolic analysis
// reused).
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/linear_solver.hpp"
#include "forward/solver/newton_counters.hpp"
#include "forward/solver/newton_state.hpp"
#include "forward/solver/nonlinear_problem.hpp"

#include <functional>
#include <string>
#include <vector>

namespace spifit::solver {

struct NewtonOptions {
  double initial_increment = 0.1;   // of the load factor
  double min_increment = 1e-5;
  double max_increment = 0.25;
  double growth = 1.5;              // after an increment converged in <= easy_iterations
  int easy_iterations = 8;  // large-rotation shell increments typically need 5-9
  double cutback = 0.25;            // increment x cutback after a failure (or the element's suggestion if smaller)
  int max_iterations = 20;
  double force_tolerance = 1e-7;    // |r| <= tol x force scale
  double displacement_tolerance = 1e-7;  // |du| <= tol x |increment|
  // Energy line search (Crisfield). Off by default: on thin shells it shortens the membrane-
  // dominated steps and slowed the roll-up 3.6x (docs/numerics-shell.md). Trials where an
  // element fails are halved whatever this says.
  bool line_search = false;
  int max_line_search = 6;
  // Predictor: the first iterate of an increment is the previous increment's free
  // displacement scaled to the new increment size, kept only when its residual is smaller
  // than that of the committed state (a moving tool drags a similar field along).
  bool extrapolate = false;
  // An increment whose residual exceeds its initial one after `divergence_after` iterations
  // is cut back at once instead of iterating to max_iterations (0: never).
  int divergence_after = 3;
  // At the minimum increment (where a failure would end the run) the force test alone decides
  // and the divergence rule is off: the displacement test compares a correction with an
  // increment of almost nothing, which an iterate cycling between elastic and plastic states
  // at a few layer points never passes although its residual meets the force tolerance
  // (docs/numerics-shell.md, "Global solution", Convergence).
  bool force_only_at_minimum = true;
  // When the force test passes and the last correction fails the displacement test, the next
  // correction is estimated with the last factorisation (one back-substitution with the
  // previous iterate's tangent) and tested instead: quadratic convergence makes it far smaller
  // than the last one, so the iteration that would only confirm it is saved (cone scenes: about
  // 10 % of the iterations). Off by default: the states it accepts differ within the
  // displacement tolerance, and on the vwall pie that was enough for the run to fail in its last
  // contour at a node that stops the fine cone70 too (docs/cone-scene.md, speed).
  bool estimate_next_correction = false;
  // Stabilised increments (docs/numerics-shell.md, "Stabilised increments"): when an increment
  // fails at the minimum increment, where the run would end, it is retried from the size that
  // first failed with viscous forces c |diag K| du (du: the increment's reduced displacement,
  // |diag K| the tangent's diagonal at the committed state; the tangent gains c |diag K| on its
  // diagonal), and the increments that follow keep them until `stabilised_increments` have
  // converged. The accepted state then carries the viscous force as an out-of-balance, which the
  // next increments remove; the dissipated work du . c |diag K| du is reported per increment and
  // in the summary. If a stabilised increment fails at the minimum increment too, c grows x10 up
  // to `max_stabilisation`. 0 (the default): off, the run ends there.
  double stabilisation = 0.0;
  double max_stabilisation = 0.0;  // 0: stabilisation x 100
  int stabilised_increments = 10;
  // Load factors that no increment steps over (increasing): an increment reaching past one
  // ends there instead, as at lambda_end; the increment size is not reduced by this.
  std::vector<double> breakpoints{};
  LinearSolverKind linear_solver = LinearSolverKind::automatic;
  int element_chunk = 2048;
  // Linear analysis: one increment, one solve from the reference state, no equilibrium
  // iterations (patch tests and the linear benchmarks).
  bool linear = false;         // elements evaluated in parallel before scattering
  // Empty when valid, else the first problem.
  std::string validate() const;
};

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

class NewtonSolver {
 public:
  NewtonSolver(NonlinearProblem& problem, const DofConstraints& constraints, NewtonOptions options = {});
  ~NewtonSolver();
  // Called after every converged increment (outputs, progress), once the problem is committed
  // and the size of the next increment chosen: state() is then a complete restart point
  // (checkpoints). Returning false stops the run.
  using IncrementCallback = std::function<bool(const IncrementReport&)>;
  NewtonSummary solve(double lambda_end = 1.0, const IncrementCallback& callback = {});
  // From the committed load factor lambda_start (a previous solve's end) to lambda_end; the
  // increment size, growth ceiling and counters start afresh (the predictor carries over).
  NewtonSummary solve(double lambda_start, double lambda_end, const IncrementCallback& callback);
  // Continues from the stepping state (set_state, or where the last solve stopped) to
  // lambda_end. With a problem restored to the state's committed load factor, the increments
  // that follow are those an uninterrupted run would have taken, and the summary's totals
  // include the state's. std::logic_error before any solve or set_state.
  NewtonSummary resume(double lambda_end, const IncrementCallback& callback);
  NewtonState state() const;
  // Throws std::invalid_argument when the predictor's size differs from the problem's DOFs.
  void set_state(const NewtonState& state);
  // One Newton iteration's building blocks, exposed for benchmarks and tests.
  struct Assembly {
    Eigen::VectorXd residual;  // reduced
    double reaction_norm = 0.0;
    ElementEvaluation failure;  // ok unless an element failed
  };
  Assembly assemble(double lambda, bool with_tangent, const Eigen::VectorXd* dg_full);
  SparseMatrix& tangent() { return *k_; }
  // The solver the next factorisation would use (automatic: by the tangent's symmetry).
  LinearSolver& linear_solver();

 private:
  NonlinearProblem& problem_;
  const DofConstraints& constraints_;
  NewtonOptions options_;
  std::unique_ptr<class ReducedAssembler> assembler_;
  std::unique_ptr<SparseMatrix> k_;
  std::unique_ptr<LinearSolver> umfpack_, cholmod_;
  std::vector<Eigen::VectorXd> re_;  // per-chunk element residuals, tangents, statuses
  std::vector<Eigen::MatrixXd> ke_;
  std::vector<ElementEvaluation> ev_;
  double element_seconds_ = 0.0, scatter_seconds_ = 0.0, linear_seconds_ = 0.0;
  // Stepping state: committed load factor, next increment, growth ceiling, totals.
  double lambda_ = 0.0, dl_ = 0.0, ceiling_ = 0.0;
  int increments_ = 0, iterations_ = 0, cutbacks_ = 0;
  // Stabilisation: current damping factor (0: off), converged increments it still lasts, totals.
  double damping_ = 0.0;
  int stabilised_left_ = 0, stabilised_ = 0;
  double viscous_work_ = 0.0, max_viscous_force_ = 0.0;
  // Factorisations and analyses of earlier solver objects (a restored state's).
  int prior_cholmod_ = 0, prior_umfpack_ = 0, prior_symbolic_ = 0;
  // Free part of the last converged increment (full DOF vector) and its load-factor size.
  Eigen::VectorXd last_increment_;
  double last_dl_ = 0.0;
  LinearSolver& umfpack();
  LinearSolver& cholmod();
  bool solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd* x, std::string* error);
  // A solve with the last factorisation (the tangent of the previous iterate): the next Newton
  // correction's estimate. false if there is none or the solve fails.
  bool solve_with_last_factor(const Eigen::VectorXd& rhs, Eigen::VectorXd* x);
  LinearSolver* last_factor_ = nullptr;  // the solver holding the last successful factorisation
  // The increment loop from the stepping state to lambda_end (solve and resume).
  NewtonSummary run(double lambda_end, const IncrementCallback& callback);
  // Returns false (with a message) when the increment fails.
  bool increment(double lambda0, double lambda1, double damping, IncrementReport* report, ElementEvaluation* failure);
};

}  // namespace spifit::solver
