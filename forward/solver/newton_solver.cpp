#include "forward/solver/newton_solver.hpp"

#include "forward/solver/preconditioned_gmres.hpp"

#include "forward/solver/convergence_test.hpp"
#include "forward/solver/line_search.hpp"
#include "forward/solver/reduced_assembler.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <omp.h>

namespace spifit::solver {
namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

NewtonSolver::NewtonSolver(NonlinearProblem& problem, const DofConstraints& constraints, NewtonOptions options)
    : problem_(problem), constraints_(constraints), options_(options), control_(options_), stabilisation_(options_) {
  if (const std::string err = options.validate(); !err.empty()) throw std::invalid_argument("Newton options: " + err);
  if (!constraints.finalized()) throw std::logic_error("DofConstraints used before finalize()");
  assembler_ = std::make_unique<ReducedAssembler>(constraints, problem.element_dofs());
  k_ = std::make_unique<SparseMatrix>(assembler_->pattern());
}

LinearSolver& NewtonSolver::umfpack() {
  if (!umfpack_) umfpack_ = make_linear_solver(LinearSolverKind::umfpack);
  return *umfpack_;
}

LinearSolver& NewtonSolver::cholmod() {
  if (!cholmod_) cholmod_ = make_linear_solver(LinearSolverKind::cholmod);
  return *cholmod_;
}

LinearSolver& NewtonSolver::linear_solver(const SparseMatrix** matrix) {
  *matrix = k_.get();
  switch (options_.linear_solver) {
    case LinearSolverKind::umfpack: return umfpack();
    case LinearSolverKind::cholmod: return cholmod();
    case LinearSolverKind::automatic: break;
  }
  if (k_->is_symmetric(1e-10)) return cholmod();
  if (!options_.symmetric_tangent) return umfpack();
  if (!k_symmetric_) k_symmetric_ = std::make_unique<SparseMatrix>(k_->pattern());
  k_symmetric_->assign_symmetric_part(*k_);
  *matrix = k_symmetric_.get();
  return cholmod();
}

NewtonSolver::~NewtonSolver() = default;

NewtonSolver::Assembly NewtonSolver::assemble(double lambda, bool with_tangent, const Eigen::VectorXd* dg_full) {
  Assembly out;
  tangent_at_iterate_ = false;
  const auto& dofs = problem_.element_dofs();
  const int ne = static_cast<int>(dofs.size());
  Eigen::VectorXd full = -problem_.external_forces(lambda);
  Eigen::VectorXd reactions = Eigen::VectorXd::Zero(problem_.num_dofs());
  if (with_tangent) k_->set_zero();
  const int chunk = std::min(options_.element_chunk, std::max(ne, 1));
  // Element buffers live as long as the solver: no allocation per iteration once sized.
  if (re_.size() != static_cast<std::size_t>(chunk)) {
    re_.resize(static_cast<std::size_t>(chunk));
    ke_.resize(static_cast<std::size_t>(chunk));
    ev_.resize(static_cast<std::size_t>(chunk));
  }
  auto& re = re_;
  auto& ke = ke_;
  auto& ev = ev_;
  Eigen::VectorXd r, dgl;  // per-element buffers, sized once (all elements have the same DOF count)
  ++(with_tangent ? counters_.tangent_assemblies : counters_.residual_assemblies);
  for (int first = 0; first < ne; first += chunk) {
    const int count = std::min(chunk, ne - first);
    auto t0 = std::chrono::steady_clock::now();
    // Dynamic chunks: elements under the tool (plastic layers, contact) cost more than the
    // rest, so static halves would leave one thread waiting (docs/design/numerics-shell.md, Assembly).
#pragma omp parallel for schedule(dynamic, 16)
    for (int i = 0; i < count; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      ev[ui] = problem_.evaluate_element(first + i, &re[ui], with_tangent ? &ke[ui] : nullptr);
    }
    counters_.element_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    // Scatter in element order: the result does not depend on the number of threads.
    for (int i = 0; i < count; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      if (!ev[ui].ok) {
        out.failure = ev[ui];
        return out;
      }
      const std::vector<int>& ed = dofs[static_cast<std::size_t>(first + i)];
      r = re[ui];
      for (std::size_t a = 0; a < ed.size(); ++a)
        if (constraints_.prescribed(ed[a])) reactions(ed[a]) += r(static_cast<Eigen::Index>(a));
      if (dg_full && with_tangent) {
        dgl.resize(static_cast<Eigen::Index>(ed.size()));
        for (std::size_t a = 0; a < ed.size(); ++a) dgl(static_cast<Eigen::Index>(a)) = (*dg_full)(ed[a]);
        if (dgl.squaredNorm() > 0.0) r.noalias() += ke[ui] * dgl;
      }
      for (std::size_t a = 0; a < ed.size(); ++a) full(ed[a]) += r(static_cast<Eigen::Index>(a));
    }
    if (with_tangent) {
      // Each thread adds its own rows of K, every element in element order: the same sums
      // as a serial scatter, bit for bit, for any number of threads.
      const int rows = k_->pattern().rows;
#pragma omp parallel
      {
        const int t = omp_get_thread_num(), threads = omp_get_num_threads();
        const int row_begin = static_cast<int>(static_cast<long>(rows) * t / threads);
        const int row_end = static_cast<int>(static_cast<long>(rows) * (t + 1) / threads);
        for (int i = 0; i < count; ++i) assembler_->add_tangent_rows(first + i, ke[static_cast<std::size_t>(i)], row_begin, row_end, k_.get());
      }
    }
    counters_.scatter_seconds += seconds_since(t0);
  }
  out.residual = constraints_.reduce(full);
  out.reaction_norm = reactions.norm();
  tangent_at_iterate_ = with_tangent;
  return out;
}

bool NewtonSolver::solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd* x, std::string* error) {
  const auto t0 = std::chrono::steady_clock::now();
  struct Clock {
    std::chrono::steady_clock::time_point t0;
    double* sink;
    ~Clock() { *sink += seconds_since(t0); }
  } clock{t0, &counters_.linear_seconds};
  last_factor_ = nullptr;
  const SparseMatrix* matrix = nullptr;
  LinearSolver& first = linear_solver(&matrix);
  if (first.factorize(*matrix) && first.solve(rhs, x)) {
    last_factor_ = &first;
    return true;
  }
  if (&first == cholmod_.get()) {
    // Not positive definite (e.g. past a limit point, or the symmetric part of a sliding
    // tangent): the general solver still applies, to the exact tangent.
    LinearSolver& general = umfpack();
    if (general.factorize(*k_) && general.solve(rhs, x)) {
      last_factor_ = &general;
      return true;
    }
    *error = general.error();
    return false;
  }
  *error = first.error();
  return false;
}

bool NewtonSolver::solve_with_last_factor(const Eigen::VectorXd& rhs, Eigen::VectorXd* x) {
  if (!last_factor_) return false;
  const auto t0 = std::chrono::steady_clock::now();
  const bool ok = last_factor_->solve(rhs, x) && x->allFinite();
  counters_.linear_seconds += seconds_since(t0);
  return ok;
}

std::string NewtonSolver::describe_largest(const Eigen::VectorXd& correction) const {
  Eigen::Index k = 0;
  if (correction.size() > 0) correction.cwiseAbs().maxCoeff(&k);
  char b[64];
  std::snprintf(b, sizeof b, "largest correction %.3g at ", correction.size() > 0 ? correction(k) : 0.0);
  return std::string(b) + problem_.describe_dof(static_cast<int>(k));
}

bool NewtonSolver::first_iterate(const Attempt& at, const Eigen::VectorXd& dg, Assembly* a, bool* at_committed, IncrementReport* report,
                                 ElementEvaluation* failure) {
  const bool has_dg = dg.squaredNorm() > 0.0;
  // A stabilised increment starts from the committed state (its viscous forces act on the
  // displacement from there).
  const bool try_predictor = at.damping == 0.0 && options_.extrapolate && predictor_.available(problem_.num_dofs());
  // With a predictor to try (and no prescribed increment, whose load needs the tangent), the
  // committed state's residual is only compared with the predicted one: no tangent for it.
  *a = assemble(at.lambda1, !try_predictor || has_dg, has_dg ? &dg : nullptr);
  if (!a->failure.ok) {
    *failure = a->failure;
    return false;
  }
  if (!try_predictor) return true;
  // The predicted iterate replaces the committed one when it is closer to equilibrium.
  problem_.set_trial(predictor_.iterate(at.lambda1 - at.lambda0, dg), 1.0);
  Assembly p = assemble(at.lambda1, true, nullptr);
  if (p.failure.ok && p.residual.norm() < a->residual.norm()) {
    problem_.accept_trial();
    *a = std::move(p);
    *at_committed = false;
    report->extrapolated = true;
    return true;
  }
  problem_.revert();
  problem_.begin_increment(at.lambda0, at.lambda1);
  *a = assemble(at.lambda1, true, has_dg ? &dg : nullptr);  // the tangent at the committed state again
  if (!a->failure.ok) {
    *failure = a->failure;
    return false;
  }
  return true;
}

bool NewtonSolver::ends_increment_likely(const ConvergenceTest& test, const IncrementReport& report, double correction) const {
  const std::vector<double>& rels = report.residual_norms;
  if (!options_.skip_final_tangent || rels.size() < 2) return false;
  // The increment's norm after the correction is at least its norm before less the correction.
  const double increment = std::max(problem_.increment_from_committed().norm() - correction, 0.0);
  return test.likely_final(rels.back(), rels[rels.size() - 2], correction, increment);
}

bool NewtonSolver::tangent_after_all(double lambda1, ElementEvaluation* failure) {
  // Predicted wrongly: the tangent at the same iterate (the same residual again).
  ++counters_.tangent_reassemblies;
  const Assembly again = assemble(lambda1, true, nullptr);
  if (again.failure.ok) return true;
  *failure = again.failure;
  return false;
}

bool NewtonSolver::increment(const Attempt& at, IncrementReport* report, ElementEvaluation* failure) {
  problem_.revert();
  problem_.begin_increment(at.lambda0, at.lambda1);
  const Eigen::VectorXd f_ext = constraints_.reduce(problem_.external_forces(at.lambda1));
  const Eigen::VectorXd dg = constraints_.prescribed_values(at.lambda1 - at.lambda0);
  const bool has_dg = dg.squaredNorm() > 0.0;
  Assembly a;
  bool first = true;  // the iterate is the committed state: the first correction carries dg
  if (!first_iterate(at, dg, &a, &first, report, failure)) return false;
  ConvergenceTest test(options_, f_ext.norm(), at.at_minimum);
  report->residual_norms.push_back(test.initial(a.residual, a.reaction_norm));
  Eigen::VectorXd r = a.residual;
  ViscousForces viscous(at.damping, *k_, r.size());
  const LineSearch line_search(options_);
  auto fail = [&](const std::string& reason, const std::string& where) {
    failure->ok = false;
    failure->reason = reason;
    if (!where.empty()) failure->where = where;
    failure->suggested_scale = options_.cutback;
    return false;
  };
  for (int it = 1; it <= options_.max_iterations; ++it) {
    Eigen::VectorXd du;
    std::string error;
    viscous.add_to_tangent(k_.get());
    if (!solve_linear(-r, &du, &error)) return fail("linear solver: " + error, {});
    const Eigen::VectorXd dfree = constraints_.expand(du);
    // An iterate likely to end the increment gets its residual alone (about 440 of 2 550 tangents
    // of line_half were assembled there and never used); the tangent follows if it does not.
    // (Not with sensitivities: their step needs the tangent at the converged iterate.)
    const bool likely_final = !first && problem_.sensitivity_count() == 0 && ends_increment_likely(test, *report, du.norm());
    // Step length: halved where an element fails, optionally the energy line search. A
    // stabilised increment's trial residual includes the viscous forces.
    Assembly trial;
    const LineSearch::Step step = line_search.run(du, r, [&](double alpha) -> const Eigen::VectorXd* {
      problem_.set_trial(first && has_dg ? Eigen::VectorXd(alpha * dfree + dg) : Eigen::VectorXd(alpha * dfree), 1.0);
      trial = assemble(at.lambda1, !likely_final, nullptr);
      if (!trial.failure.ok) return nullptr;
      viscous.add_to_residual(&trial.residual, du, alpha);
      return &trial.residual;
    });
    report->line_searches += step.searches;
    if (!step.ok) {
      *failure = trial.failure;
      return false;
    }
    problem_.accept_trial();
    first = false;
    r = trial.residual;
    viscous.accept(du, step.alpha);
    report->iterations = it;
    const double rel = test.relative(r, trial.reaction_norm);
    report->residual_norms.push_back(rel);
    if (test.check_residual(rel) == Verdict::diverged) return fail(test.failure_reason(Verdict::diverged, it, rel), describe_largest(dfree));
    if (options_.linear) return true;
    const double inc = problem_.increment_from_committed().norm();
    const double correction = step.alpha * du.norm();
    report->correction_norms.push_back(correction);
    const Verdict v = test.check(it, rel, correction, inc, [&](double* norm) {
      Eigen::VectorXd next;
      if (!solve_with_last_factor(-r, &next)) return false;
      *norm = next.norm();
      return true;
    });
    if (v == Verdict::diverging) return fail(test.failure_reason(v, it, rel), describe_largest(dfree));
    if (v != Verdict::next_iteration) {
      report->estimated = v == Verdict::estimated;
      report->force_only = v == Verdict::force_only;
      viscous.report(test.force_scale(), report);
      return true;
    }
    if (it == options_.max_iterations) {
      failure->where = describe_largest(dfree);
      break;
    }
    if (likely_final && !tangent_after_all(at.lambda1, failure)) return false;
  }
  return fail(test.failure_reason(Verdict::next_iteration, options_.max_iterations, report->residual_norms.back()), {});
}

NewtonSummary NewtonSolver::solve(double lambda_end, const IncrementCallback& callback) { return solve(0.0, lambda_end, callback); }

NewtonSummary NewtonSolver::solve(double lambda_start, double lambda_end, const IncrementCallback& callback) {
  control_.start(lambda_start, lambda_end);
  counters_.increments = counters_.iterations = counters_.cutbacks = 0;
  stabilisation_.reset();
  counters_.stabilised_increments = 0;
  counters_.viscous_work = counters_.max_viscous_force = 0.0;
  return run(lambda_end, callback);
}

NewtonCounters NewtonSolver::counters() const {
  NewtonCounters c = counters_;
  c.cholmod_factorisations += cholmod_ ? cholmod_->numeric_factorisations() : 0;
  c.umfpack_factorisations += umfpack_ ? umfpack_->numeric_factorisations() : 0;
  c.symbolic_analyses += (cholmod_ ? cholmod_->symbolic_analyses() : 0) + (umfpack_ ? umfpack_->symbolic_analyses() : 0);
  return c;
}

NewtonState NewtonSolver::state() const {
  NewtonState s;
  s.lambda = control_.lambda();
  s.increment = control_.size();
  s.ceiling = control_.ceiling();
  s.last_increment = predictor_.last_increment();
  s.last_increment_size = predictor_.last_size();
  s.damping = stabilisation_.damping();
  s.stabilised_left = stabilisation_.increments_left();
  s.counters = counters();
  s.sensitivities = problem_.sensitivity_count() > 0;
  if (s.sensitivities) s.sensitivity_solves = sensitivity_stats_;
  return s;
}

void NewtonSolver::set_state(const NewtonState& s) {
  if (s.last_increment.size() != 0 && s.last_increment.size() != problem_.num_dofs())
    throw std::invalid_argument("Newton state: predictor of " + std::to_string(s.last_increment.size()) + " DOFs, the problem has " +
                                std::to_string(problem_.num_dofs()));
  control_.restore(s.lambda, s.increment, s.ceiling);
  predictor_.restore(s.last_increment, s.last_increment_size);
  stabilisation_.restore(s.damping, s.stabilised_left);
  // The factorisations of this solver's own objects are added by counters().
  counters_ = s.counters;
  counters_.cholmod_factorisations -= cholmod_ ? cholmod_->numeric_factorisations() : 0;
  counters_.umfpack_factorisations -= umfpack_ ? umfpack_->numeric_factorisations() : 0;
  counters_.symbolic_analyses -= (cholmod_ ? cholmod_->symbolic_analyses() : 0) + (umfpack_ ? umfpack_->symbolic_analyses() : 0);
  if (s.sensitivities) sensitivity_stats_ = s.sensitivity_solves;
}

NewtonSummary NewtonSolver::resume(double lambda_end, const IncrementCallback& callback) {
  if (!control_.started()) throw std::logic_error("NewtonSolver::resume without a stepping state (solve or set_state first)");
  return run(lambda_end, callback);
}

bool NewtonSolver::after_failure(double lambda0, double lambda1, const ElementEvaluation& failure, std::string* message) {
  control_.failed(lambda1);
  problem_.revert();
  ++counters_.cutbacks;
  if (!control_.at_minimum()) {
    control_.cut_back(failure.suggested_scale);
    return true;
  }
  // Where the run would end: retry from the size that first failed, with viscous forces (or ten
  // times stronger ones), for the next stabilised_increments converged increments.
  if (stabilisation_.escalate()) {
    control_.retry_first_failed();
    return true;
  }
  char buf[200];
  std::snprintf(buf, sizeof buf, "increment from load factor %.6g failed at the minimum increment %.3g: ", lambda0, control_.size());
  *message = buf + failure.reason + (failure.where.empty() ? "" : " (" + failure.where + ")");
  if (stabilisation_.damping() > 0.0) {
    std::snprintf(buf, sizeof buf, " (stabilised with damping factor %.3g, the largest allowed)", stabilisation_.damping());
    *message += buf;
  }
  return false;
}

bool NewtonSolver::sensitivity_step(double lambda1, std::string* message) {
  // The tangent at the converged iterate: the last assembly's when it had one (a run with
  // sensitivities assembles it at every iterate) and it was exact, else assembled now, exact
  // (where layers started the increment at rest, Newton had their last elastic-plastic tangents:
  // a solve with those moved the derivatives at increments where nothing moved).
  if (!tangent_at_iterate_ || !problem_.tangent_was_exact()) {
    problem_.set_exact_tangents(true);
    const Assembly a = assemble(lambda1, true, nullptr);
    problem_.set_exact_tangents(false);
    if (!a.failure.ok) {
      *message = "sensitivities at load factor " + std::to_string(lambda1) + ": " + a.failure.where + ": " + a.failure.reason;
      return false;
    }
  }
  Eigen::MatrixXd load;
  const ElementEvaluation le = problem_.sensitivity_load(&load);
  if (!le.ok) {
    *message = "sensitivities at load factor " + std::to_string(lambda1) + ": " + le.where + ": " + le.reason;
    return false;
  }
  const auto t0 = std::chrono::steady_clock::now();
  ++sensitivity_stats_.increments;
  // The exact tangent's solves: GMRES preconditioned by Newton's factor in hand (the tangent at
  // the previous iterate, or its symmetric part), else -- no factor, or GMRES not converged -- a
  // factorisation of the exact tangent of its own: UMFPACK unless it is symmetric (CHOLMOD).
  bool factorised = false;
  Eigen::MatrixXd du(problem_.num_dofs(), load.cols());
  for (Eigen::Index k = 0; k < load.cols(); ++k) {
    const Eigen::VectorXd rhs = -constraints_.reduce(load.col(k));
    Eigen::VectorXd x;
    if (!factorised && last_factor_) {
      const GmresResult g = preconditioned_gmres([this](const Eigen::VectorXd& v) { return k_->multiply(v); },
                                                 [this](const Eigen::VectorXd& v, Eigen::VectorXd* z) { return last_factor_->solve(v, z); }, rhs,
                                                 &x, kSensitivityGmresTolerance, kSensitivityGmresIterations);
      sensitivity_stats_.gmres_iterations += g.iterations;
      if (g.converged) {
        ++sensitivity_stats_.gmres_solves;
        du.col(k) = constraints_.expand(x);
        continue;
      }
    }
    if (!factorised) {
      const bool symmetric = k_->is_symmetric(1e-10);
      if (!sensitivity_solver_ || sensitivity_symmetric_ != symmetric) {
        sensitivity_solver_ = make_linear_solver(symmetric ? LinearSolverKind::cholmod : LinearSolverKind::umfpack);
        sensitivity_symmetric_ = symmetric;
      }
      if (!sensitivity_solver_->factorize(*k_)) {
        *message = "sensitivities at load factor " + std::to_string(lambda1) + ": the tangent: " + sensitivity_solver_->error();
        return false;
      }
      factorised = true;
      ++sensitivity_stats_.factorisations;
    }
    if (!sensitivity_solver_->solve(rhs, &x)) {
      *message = "sensitivities at load factor " + std::to_string(lambda1) + ": " + sensitivity_solver_->error();
      return false;
    }
    du.col(k) = constraints_.expand(x);
  }
  sensitivity_stats_.solve_seconds += seconds_since(t0);
  const ElementEvaluation ue = problem_.update_sensitivities(du);
  if (!ue.ok) {
    *message = "sensitivities at load factor " + std::to_string(lambda1) + ": " + ue.where + ": " + ue.reason;
    return false;
  }
  return true;
}

NewtonSummary NewtonSolver::run(double lambda_end, const IncrementCallback& callback) {
  NewtonSummary summary;
  control_.begin_run();
  while (!control_.reached(lambda_end)) {
    const double lambda = control_.lambda();
    const double lambda1 = control_.next_end(lambda_end);
    IncrementReport report;
    report.index = counters_.increments + 1;
    report.lambda = lambda1;
    report.increment = lambda1 - lambda;
    ElementEvaluation failure;
    const Attempt attempt{lambda, lambda1, stabilisation_.damping(), options_.force_only_at_minimum && control_.at_minimum()};
    const bool ok = increment(attempt, &report, &failure);
    counters_.iterations += report.iterations;
    if (!ok) {
      if (!after_failure(lambda, lambda1, failure, &summary.message)) break;
      continue;
    }
    stabilisation_.converged(report, &counters_);
    if (problem_.sensitivity_count() > 0 && !sensitivity_step(lambda1, &summary.message)) break;
    if (options_.extrapolate) predictor_.record(problem_, constraints_, lambda, lambda1);
    problem_.commit(lambda1);
    ++counters_.increments;
    // The next size is chosen before the callback, so that state() there is where the run
    // continues from.
    control_.converged(lambda1, report.iterations, lambda_end);
    summary.history.push_back(report);
    if (callback && !callback(report)) {
      summary.message = "stopped by the caller at load factor " + std::to_string(control_.lambda());
      break;
    }
  }
  summary.lambda = control_.lambda();
  summary.converged = summary.lambda >= lambda_end - 1e-12;
  if (summary.converged && summary.message.empty()) summary.message = "converged";
  summary.counters = counters();
  return summary;
}

}  // namespace spifit::solver
