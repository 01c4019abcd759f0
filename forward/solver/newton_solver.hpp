#pragma once
// Implicit static solution (docs/design/numerics-shell.md, "Global solution"): load factor lambda
// from 0 to 1 in increments; Newton-Raphson on the reduced residual. NewtonSolver assembles
// (parallel element evaluation with OpenMP, assembly in element order, so results do not depend
// on the thread count), solves the linear systems (UMFPACK or CHOLMOD on a pattern built once,
// symbolic analysis reused) and runs the increments; the rules it applies are separate units:
// Predictor (first iterate), ViscousForces and Stabilisation (stabilised increments),
// LineSearch (step length), ConvergenceTest (accept and give-up rules) and IncrementControl
// (increment sizes).
#include "forward/solver/dof_constraints.hpp"
#include "forward/solver/increment_control.hpp"
#include "forward/solver/linear_solver.hpp"
#include "forward/solver/newton_counters.hpp"
#include "forward/solver/newton_options.hpp"
#include "forward/solver/newton_report.hpp"
#include "forward/solver/newton_state.hpp"
#include "forward/solver/nonlinear_problem.hpp"
#include "forward/solver/predictor.hpp"
#include "forward/solver/stabilisation.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spifit::solver {

class ConvergenceTest;

class NewtonSolver {
 public:
  NewtonSolver(NonlinearProblem& problem, const DofConstraints& constraints, NewtonOptions options = {});
  ~NewtonSolver();
  NewtonSolver(const NewtonSolver&) = delete;  // its units refer to its options
  NewtonSolver& operator=(const NewtonSolver&) = delete;
  // Called after every converged increment (outputs, progress), once the problem is committed
  // and the size of the next increment chosen: state() is then a complete restart point
  // (checkpoints). Returning false stops the run.
  using IncrementCallback = std::function<bool(const IncrementReport&)>;
  NewtonSummary solve(double lambda_end = 1.0, const IncrementCallback& callback = {});
  // From the committed load factor lambda_start (a previous solve's end) to lambda_end; the
  // increment size, growth ceiling, stabilisation and counters start afresh (the predictor
  // carries over).
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
  // The solver the next factorisation would use (automatic: by the tangent's symmetry) and the
  // matrix it factorises: K, or its symmetric part (NewtonOptions::symmetric_tangent), which
  // this call then computes.
  LinearSolver& linear_solver(const SparseMatrix** matrix);
  // The direct differentiation's solves so far (NonlinearProblem::sensitivity_count > 0).
  using SensitivitySolveStats = solver::SensitivitySolveStats;
  const SensitivitySolveStats& sensitivity_stats() const { return sensitivity_stats_; }

 private:
  NonlinearProblem& problem_;
  const DofConstraints& constraints_;
  NewtonOptions options_;
  std::unique_ptr<class ReducedAssembler> assembler_;
  std::unique_ptr<SparseMatrix> k_;
  std::unique_ptr<SparseMatrix> k_symmetric_;  // (K + K^T) / 2 (NewtonOptions::symmetric_tangent)
  std::unique_ptr<LinearSolver> umfpack_, cholmod_;
  std::vector<Eigen::VectorXd> re_;  // per-chunk element residuals, tangents, statuses
  std::vector<Eigen::MatrixXd> ke_;
  std::vector<ElementEvaluation> ev_;
  // Stepping state: committed load factor, increment sizes, predictor, damping.
  IncrementControl control_;
  Predictor predictor_;
  Stabilisation stabilisation_;
  // Totals; its factorisation counts are those of earlier solver objects (a restored state's),
  // counters() adds the current ones.
  NewtonCounters counters_;
  NewtonCounters counters() const;
  LinearSolver& umfpack();
  LinearSolver& cholmod();
  bool solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd* x, std::string* error);
  // A solve with the last factorisation (the tangent of the previous iterate): the next Newton
  // correction's estimate. false if there is none or the solve fails.
  bool solve_with_last_factor(const Eigen::VectorXd& rhs, Eigen::VectorXd* x);
  LinearSolver* last_factor_ = nullptr;  // the solver holding the last successful factorisation
  // Direct differentiation after a converged increment (NonlinearProblem::sensitivity_count):
  // one solve per parameter with the tangent at the converged iterate: GMRES preconditioned by
  // Newton's last factor (left as it is), or a factorisation by a solver of its own. false
  // (with the message) on failure.
  bool sensitivity_step(double lambda1, std::string* message);
  std::unique_ptr<LinearSolver> sensitivity_solver_;
  SensitivitySolveStats sensitivity_stats_;
  // GMRES on the exact tangent with Newton's factor: |residual| <= 1e-12 |rhs| within 20 of its
  // back-substitutions, else the tangent is factorised.
  static constexpr double kSensitivityGmresTolerance = 1e-12;
  static constexpr int kSensitivityGmresIterations = 20;
  bool tangent_at_iterate_ = false;  // the last assembly's tangent is k_ (its iterate's)
  bool sensitivity_symmetric_ = false;
  // The increment loop from the stepping state to lambda_end (solve and resume).
  NewtonSummary run(double lambda_end, const IncrementCallback& callback);
  // After a failed attempt: cut back, or at the minimum increment stabilise or give up (false,
  // with the message).
  bool after_failure(double lambda0, double lambda1, const ElementEvaluation& failure, std::string* message);
  // Where a correction (full DOF vector) is largest: named in the message of a failed increment.
  std::string describe_largest(const Eigen::VectorXd& correction) const;
  // One attempt of an increment from the committed lambda0 to lambda1.
  struct Attempt {
    double lambda0 = 0.0, lambda1 = 0.0;
    double damping = 0.0;     // of the viscous forces (0: none)
    bool at_minimum = false;  // minimum size, force test alone (NewtonOptions::force_only_at_minimum)
  };
  // Returns false (with the failure) when the attempt fails.
  bool increment(const Attempt& attempt, IncrementReport* report, ElementEvaluation* failure);
  // Whether the iterate a correction of this norm leads to will likely end the increment
  // (NewtonOptions::skip_final_tangent; ConvergenceTest::likely_final).
  bool ends_increment_likely(const ConvergenceTest& test, const IncrementReport& report, double correction) const;
  // The tangent of an iterate assembled without it that did not end its increment; false (with
  // the failure) if an element fails.
  bool tangent_after_all(double lambda1, ElementEvaluation* failure);
  // The first iterate (committed state, or the predictor's when closer to equilibrium) and its
  // assembly with the tangent; *at_committed false when the predictor's was kept.
  bool first_iterate(const Attempt& attempt, const Eigen::VectorXd& dg, Assembly* a, bool* at_committed, IncrementReport* report,
                     ElementEvaluation* failure);
};

}  // namespace spifit::solver
