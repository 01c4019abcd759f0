#include "forward/solver/newton_solver.hpp"

#include "forward/solver/reduced_assembler.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace spifit::solver {
namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

std::string NewtonOptions::validate() const {
  if (!(min_increment > 0.0 && min_increment <= initial_increment && initial_increment <= max_increment && max_increment <= 1.0)) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "min_increment %g, initial_increment %g, max_increment %g: need 0 < min <= initial <= max <= 1",
                  min_increment, initial_increment, max_increment);
    return buf;
  }
  if (!(growth >= 1.0)) return "growth must be >= 1";
  if (!(cutback > 0.0 && cutback < 1.0)) return "cutback must be in (0, 1)";
  if (max_iterations < 1) return "max_iterations must be >= 1";
  if (!(force_tolerance > 0.0) || !(displacement_tolerance > 0.0)) return "tolerances must be > 0";
  if (max_line_search < 0) return "max_line_search must be >= 0";
  if (element_chunk < 1) return "element_chunk must be >= 1";
  if (!(stabilisation >= 0.0 && std::isfinite(stabilisation))) return "stabilisation must be >= 0";
  if (!(max_stabilisation == 0.0 || (std::isfinite(max_stabilisation) && max_stabilisation >= stabilisation)))
    return "max_stabilisation must be 0 or >= stabilisation";
  if (stabilised_increments < 1) return "stabilised_increments must be >= 1";
  for (std::size_t i = 0; i < breakpoints.size(); ++i)
    if (!std::isfinite(breakpoints[i]) || (i > 0 && !(breakpoints[i] > breakpoints[i - 1]))) return "breakpoints must be finite and increasing";
  return {};
}

NewtonSolver::NewtonSolver(NonlinearProblem& problem, const DofConstraints& constraints, NewtonOptions options)
    : problem_(problem), constraints_(constraints), options_(options) {
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

LinearSolver& NewtonSolver::linear_solver() {
  switch (options_.linear_solver) {
    case LinearSolverKind::umfpack: return umfpack();
    case LinearSolverKind::cholmod: return cholmod();
    case LinearSolverKind::automatic: break;
  }
  return k_->is_symmetric(1e-10) ? cholmod() : umfpack();
}

NewtonSolver::~NewtonSolver() = default;

NewtonSolver::Assembly NewtonSolver::assemble(double lambda, bool with_tangent, const Eigen::VectorXd* dg_full) {
  Assembly out;
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
  for (int first = 0; first < ne; first += chunk) {
    const int count = std::min(chunk, ne - first);
    auto t0 = std::chrono::steady_clock::now();
    // Dynamic chunks: elements under the tool (plastic layers, contact) cost more than the
    // rest, so static halves left one thread waiting (cone70 fine: element loop -14 %).
#pragma omp parallel for schedule(dynamic, 16)
    for (int i = 0; i < count; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      ev[ui] = problem_.evaluate_element(first + i, &re[ui], with_tangent ? &ke[ui] : nullptr);
    }
    element_seconds_ += seconds_since(t0);
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
      if (with_tangent) assembler_->add(first + i, re[ui], &ke[ui], nullptr, nullptr, k_.get());
    }
    scatter_seconds_ += seconds_since(t0);
  }
  out.residual = constraints_.reduce(full);
  out.reaction_norm = reactions.norm();
  return out;
}

bool NewtonSolver::solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd* x, std::string* error) {
  const auto t0 = std::chrono::steady_clock::now();
  struct Clock {
    std::chrono::steady_clock::time_point t0;
    double* sink;
    ~Clock() { *sink += seconds_since(t0); }
  } clock{t0, &linear_seconds_};
  last_factor_ = nullptr;
  LinearSolver& first = linear_solver();
  if (first.factorize(*k_) && first.solve(rhs, x)) {
    last_factor_ = &first;
    return true;
  }
  if (&first == cholmod_.get()) {
    // Not positive definite (e.g. past a limit point): the general solver still applies.
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
  linear_seconds_ += seconds_since(t0);
  return ok;
}

bool NewtonSolver::increment(double lambda0, double lambda1, double damping, IncrementReport* report, ElementEvaluation* failure) {
  problem_.revert();
  problem_.begin_increment(lambda0, lambda1);
  const Eigen::VectorXd f_ext = constraints_.reduce(problem_.external_forces(lambda1));
  const Eigen::VectorXd dg = constraints_.prescribed_values(lambda1 - lambda0);
  const bool has_dg = dg.squaredNorm() > 0.0;
  // A stabilised increment starts from the committed state (its viscous forces act on the
  // displacement from there).
  const bool try_predictor = damping == 0.0 && options_.extrapolate && last_dl_ > 0.0 && last_increment_.size() == problem_.num_dofs();
  // With a predictor to try (and no prescribed increment, whose load needs the tangent), the
  // committed state's residual is only compared with the predicted one: no tangent for it.
  Assembly a = assemble(lambda1, !try_predictor || has_dg, has_dg ? &dg : nullptr);
  if (!a.failure.ok) {
    *failure = a.failure;
    return false;
  }
  bool first = true;
  if (try_predictor) {
    // The predicted iterate replaces the committed one when it is closer to equilibrium.
    const double scale = (lambda1 - lambda0) / last_dl_;
    problem_.set_trial(scale * last_increment_ + dg, 1.0);
    Assembly p = assemble(lambda1, true, nullptr);
    if (p.failure.ok && p.residual.norm() < a.residual.norm()) {
      problem_.accept_trial();
      a = std::move(p);
      first = false;
      report->extrapolated = true;
    } else {
      problem_.revert();
      problem_.begin_increment(lambda0, lambda1);
      a = assemble(lambda1, true, has_dg ? &dg : nullptr);  // the tangent at the committed state again
      if (!a.failure.ok) {
        *failure = a.failure;
        return false;
      }
    }
  }
  // Force scale of the convergence test: external forces and the reactions of the current
  // iterate (the first residual only for the report, where both may still vanish).
  const double r0 = a.residual.norm() / std::max({f_ext.norm(), a.reaction_norm, a.residual.norm(), 1e-300});
  report->residual_norms.push_back(r0);
  Eigen::VectorXd r = a.residual;
  // Stabilised: viscous forces c |diag K| du_bar on the reduced displacement of the increment
  // (du_bar, the sum of the accepted corrections; the prescribed part is not a reduced unknown),
  // with |diag K| of the committed state's tangent, fixed for the increment. r holds the
  // residual with them, the tangent gets c |diag K| on its diagonal before every solve.
  Eigen::VectorXd viscosity, du_bar;
  if (damping > 0.0) {
    viscosity = damping * k_->diagonal().cwiseAbs();
    du_bar = Eigen::VectorXd::Zero(r.size());
  }
  double force_scale = 1e-300;
  auto accept = [&]() {
    if (damping > 0.0) {
      const Eigen::VectorXd v = viscosity.cwiseProduct(du_bar);
      report->damping = damping;
      report->viscous_work = du_bar.dot(v);
      report->viscous_force = v.norm() / force_scale;
    }
    return true;
  };
  // At the minimum increment a failure ends the run: the force test alone decides there, and
  // no divergence cut-back is taken (there is nothing smaller to cut back to).
  const bool final_size = options_.force_only_at_minimum && dl_ <= options_.min_increment * (1.0 + 1e-12);
  for (int it = 1; it <= options_.max_iterations; ++it) {
    Eigen::VectorXd du;
    std::string error;
    if (damping > 0.0) k_->add_to_diagonal(viscosity);
    if (!solve_linear(-r, &du, &error)) {
      failure->ok = false;
      failure->reason = "linear solver: " + error;
      failure->suggested_scale = options_.cutback;
      return false;
    }
    const Eigen::VectorXd dfree = constraints_.expand(du);
    // Where the correction is largest: named in the message if the increment fails.
    auto largest_correction = [&]() {
      Eigen::Index k = 0;
      if (dfree.size() > 0) dfree.cwiseAbs().maxCoeff(&k);
      char b[64];
      std::snprintf(b, sizeof b, "largest correction %.3g at ", dfree.size() > 0 ? dfree(k) : 0.0);
      return std::string(b) + problem_.describe_dof(static_cast<int>(k));
    };
    // A trial where an element fails is halved (always). Optional energy line search on
    // s(alpha) = du . r(alpha) (secant steps, alpha in [0.1, 1]).
    const double s0 = du.dot(r);
    double alpha = 1.0;
    Assembly trial;
    for (int ls = 0;; ++ls) {
      problem_.set_trial(first && has_dg ? Eigen::VectorXd(alpha * dfree + dg) : Eigen::VectorXd(alpha * dfree), 1.0);
      trial = assemble(lambda1, true, nullptr);
      if (damping > 0.0 && trial.failure.ok) trial.residual += viscosity.cwiseProduct(du_bar + alpha * du);
      if (!trial.failure.ok) {
        if (ls < options_.max_line_search && alpha > 0.1) {  // a failed trial: try a shorter step first
          alpha *= 0.5;
          ++report->line_searches;
          continue;
        }
        *failure = trial.failure;
        return false;
      }
      if (!options_.line_search || ls >= options_.max_line_search || !(s0 < 0.0)) break;
      const double s1 = du.dot(trial.residual);
      if (std::abs(s1) <= 0.8 * std::abs(s0) || !std::isfinite(s1)) break;
      const double next = std::clamp(alpha * s0 / (s0 - s1), 0.1, 1.0);
      if (std::abs(next - alpha) < 0.05) break;
      alpha = next;
      ++report->line_searches;
    }
    problem_.accept_trial();
    first = false;
    r = trial.residual;
    if (damping > 0.0) du_bar += alpha * du;
    report->iterations = it;
    force_scale = std::max({f_ext.norm(), trial.reaction_norm, 1e-300});
    const double rel = r.norm() / force_scale;
    report->residual_norms.push_back(rel);
    if (!std::isfinite(rel) || rel > 1e10) {
      failure->ok = false;
      failure->reason = "Newton iterations diverged (relative residual " + std::to_string(rel) + ")";
      failure->where = largest_correction();
      failure->suggested_scale = options_.cutback;
      return false;
    }
    if (options_.linear) return true;
    const double inc = problem_.increment_from_committed().norm();
    const double step = alpha * du.norm();
    report->correction_norms.push_back(step);
    if (rel <= options_.force_tolerance && (step <= options_.displacement_tolerance * std::max(inc, 1e-300) ||
                                            rel <= 1e-3 * options_.force_tolerance))
      return accept();
    // The force test passed but the last correction was large (it came from a worse iterate):
    // the next correction, estimated with the factorisation already at hand (one back-
    // substitution, no assembly), decides instead of a further iteration.
    if (rel <= options_.force_tolerance && options_.estimate_next_correction) {
      Eigen::VectorXd next;
      if (solve_with_last_factor(-r, &next) && next.norm() <= options_.displacement_tolerance * std::max(inc, 1e-300)) {
        report->estimated = true;
        return accept();
      }
    }
    if (final_size && rel <= options_.force_tolerance) {
      report->force_only = true;
      return accept();
    }
    if (!final_size && options_.divergence_after > 0 && it >= options_.divergence_after && rel > r0) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "Newton iterations diverging (relative residual %.3g after %d iterations, %.3g at the start)", rel, it, r0);
      failure->ok = false;
      failure->reason = buf;
      failure->where = largest_correction();
      failure->suggested_scale = options_.cutback;
      return false;
    }
    if (it == options_.max_iterations) failure->where = largest_correction();
  }
  failure->ok = false;
  char buf[160];
  std::snprintf(buf, sizeof buf, "no convergence in %d iterations (relative residual %.3g)", options_.max_iterations,
                report->residual_norms.back());
  failure->reason = buf;
  failure->suggested_scale = options_.cutback;
  return false;
}

NewtonSummary NewtonSolver::solve(double lambda_end, const IncrementCallback& callback) { return solve(0.0, lambda_end, callback); }

NewtonSummary NewtonSolver::solve(double lambda_start, double lambda_end, const IncrementCallback& callback) {
  lambda_ = lambda_start;
  dl_ = options_.linear ? lambda_end - lambda_start : options_.initial_increment;
  ceiling_ = options_.max_increment;
  increments_ = iterations_ = cutbacks_ = 0;
  damping_ = 0.0;
  stabilised_left_ = stabilised_ = 0;
  viscous_work_ = max_viscous_force_ = 0.0;
  return run(lambda_end, callback);
}

NewtonState NewtonSolver::state() const {
  NewtonState s;
  s.lambda = lambda_;
  s.increment = dl_;
  s.ceiling = ceiling_;
  s.last_increment = last_increment_;
  s.last_increment_size = last_dl_;
  s.damping = damping_;
  s.stabilised_left = stabilised_left_;
  NewtonCounters& c = s.counters;
  c.increments = increments_;
  c.iterations = iterations_;
  c.cutbacks = cutbacks_;
  c.cholmod_factorisations = prior_cholmod_ + (cholmod_ ? cholmod_->numeric_factorisations() : 0);
  c.umfpack_factorisations = prior_umfpack_ + (umfpack_ ? umfpack_->numeric_factorisations() : 0);
  c.symbolic_analyses = prior_symbolic_ + (cholmod_ ? cholmod_->symbolic_analyses() : 0) + (umfpack_ ? umfpack_->symbolic_analyses() : 0);
  c.element_seconds = element_seconds_;
  c.scatter_seconds = scatter_seconds_;
  c.linear_seconds = linear_seconds_;
  c.stabilised_increments = stabilised_;
  c.viscous_work = viscous_work_;
  c.max_viscous_force = max_viscous_force_;
  return s;
}

void NewtonSolver::set_state(const NewtonState& s) {
  if (s.last_increment.size() != 0 && s.last_increment.size() != problem_.num_dofs())
    throw std::invalid_argument("Newton state: predictor of " + std::to_string(s.last_increment.size()) + " DOFs, the problem has " +
                                std::to_string(problem_.num_dofs()));
  lambda_ = s.lambda;
  dl_ = s.increment;
  ceiling_ = s.ceiling;
  last_increment_ = s.last_increment;
  last_dl_ = s.last_increment_size;
  damping_ = s.damping;
  stabilised_left_ = s.stabilised_left;
  const NewtonCounters& c = s.counters;
  increments_ = c.increments;
  iterations_ = c.iterations;
  cutbacks_ = c.cutbacks;
  prior_cholmod_ = c.cholmod_factorisations - (cholmod_ ? cholmod_->numeric_factorisations() : 0);
  prior_umfpack_ = c.umfpack_factorisations - (umfpack_ ? umfpack_->numeric_factorisations() : 0);
  prior_symbolic_ = c.symbolic_analyses - (cholmod_ ? cholmod_->symbolic_analyses() : 0) - (umfpack_ ? umfpack_->symbolic_analyses() : 0);
  element_seconds_ = c.element_seconds;
  scatter_seconds_ = c.scatter_seconds;
  linear_seconds_ = c.linear_seconds;
  stabilised_ = c.stabilised_increments;
  viscous_work_ = c.viscous_work;
  max_viscous_force_ = c.max_viscous_force;
}

NewtonSummary NewtonSolver::resume(double lambda_end, const IncrementCallback& callback) {
  if (!(dl_ > 0.0 && ceiling_ > 0.0)) throw std::logic_error("NewtonSolver::resume without a stepping state (solve or set_state first)");
  return run(lambda_end, callback);
}

NewtonSummary NewtonSolver::run(double lambda_end, const IncrementCallback& callback) {
  NewtonSummary summary;
  double first_failed = 0.0;  // size of the first failed attempt since the last converged increment
  const double max_damping = options_.max_stabilisation > 0.0 ? options_.max_stabilisation : 100.0 * options_.stabilisation;
  while (lambda_ < lambda_end - 1e-12) {
    const double lambda = lambda_;
    double lambda1 = std::min(lambda + dl_, lambda_end);
    if (lambda_end - lambda1 < 1e-3 * dl_) lambda1 = lambda_end;
    // The next breakpoint after lambda: the increment ends there (also when it would end just short of it).
    const auto& bp = options_.breakpoints;
    const auto next = std::upper_bound(bp.begin(), bp.end(), lambda + 1e-12);
    if (next != bp.end() && *next < lambda_end && *next - lambda1 < 1e-3 * dl_) lambda1 = *next;
    IncrementReport report;
    report.index = increments_ + 1;
    report.lambda = lambda1;
    report.increment = lambda1 - lambda;
    ElementEvaluation failure;
    const bool ok = increment(lambda, lambda1, damping_, &report, &failure);
    iterations_ += report.iterations;
    if (ok) {
      first_failed = 0.0;
      if (report.damping > 0.0) {
        ++stabilised_;
        viscous_work_ += report.viscous_work;
        max_viscous_force_ = std::max(max_viscous_force_, report.viscous_force);
        if (--stabilised_left_ <= 0) damping_ = 0.0;
      }
      if (options_.extrapolate) {
        last_increment_ = problem_.increment_from_committed() - constraints_.prescribed_values(lambda1 - lambda);
        last_dl_ = lambda1 - lambda;
      }
      problem_.commit(lambda1);
      lambda_ = lambda1;
      ++increments_;
      // Growth stays below a size that failed recently; that ceiling relaxes slowly. Chosen
      // before the callback, so that state() there is where the run continues from.
      ceiling_ = std::min(options_.max_increment, ceiling_ * 1.1);
      if (report.iterations <= options_.easy_iterations) dl_ = std::min(ceiling_, dl_ * options_.growth);
      summary.history.push_back(report);
      if (callback && !callback(report)) {
        summary.message = "stopped by the caller at load factor " + std::to_string(lambda_);
        break;
      }
      continue;
    }
    ceiling_ = std::max(options_.min_increment, 0.75 * (lambda1 - lambda));
    problem_.revert();
    ++cutbacks_;
    if (first_failed == 0.0) first_failed = lambda1 - lambda;
    const double s = std::min(options_.cutback, failure.suggested_scale);
    if (dl_ <= options_.min_increment * (1.0 + 1e-12)) {
      if (options_.stabilisation > 0.0 && damping_ < max_damping * (1.0 - 1e-12)) {
        // Where the run would end: retry from the size that first failed, with viscous forces
        // (or ten times stronger ones), for the next stabilised_increments converged increments.
        damping_ = damping_ > 0.0 ? std::min(max_damping, 10.0 * damping_) : options_.stabilisation;
        stabilised_left_ = options_.stabilised_increments;
        dl_ = std::max(options_.min_increment, first_failed);
        ceiling_ = std::max(ceiling_, dl_);
        first_failed = 0.0;
        continue;
      }
      char buf[200];
      std::snprintf(buf, sizeof buf, "increment from load factor %.6g failed at the minimum increment %.3g: ", lambda, dl_);
      summary.message = buf + failure.reason + (failure.where.empty() ? "" : " (" + failure.where + ")");
      if (damping_ > 0.0) {
        std::snprintf(buf, sizeof buf, " (stabilised with damping factor %.3g, the largest allowed)", damping_);
        summary.message += buf;
      }
      break;
    }
    dl_ = std::max(options_.min_increment, dl_ * s);
  }
  const NewtonState st = state();
  summary.lambda = st.lambda;
  summary.converged = summary.lambda >= lambda_end - 1e-12;
  if (summary.converged && summary.message.empty()) summary.message = "converged";
  summary.counters = st.counters;
  return summary;
}

}  // namespace spifit::solver
