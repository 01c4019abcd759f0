#include "forward/solver/explicit_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace spifit::solver {
namespace {

// The output points in (start, end]: every `interval` of the load factor, the stops, the end.
std::vector<double> output_points(const ExplicitSchedule& s) {
  std::vector<double> p;
  const double span = s.lambda_end - s.lambda_start;
  const auto n = static_cast<long>(std::ceil(span / s.output_interval - 1e-9));
  for (long k = 1; k < n; ++k) p.push_back(s.lambda_start + static_cast<double>(k) * s.output_interval);
  for (double l : s.stops)
    if (l > s.lambda_start && l < s.lambda_end) p.push_back(l);
  p.push_back(s.lambda_end);
  std::sort(p.begin(), p.end());
  std::vector<double> out;
  for (double l : p)
    if (out.empty() || l - out.back() > 1e-12) out.push_back(l);
  return out;
}

}  // namespace

ExplicitSolver::ExplicitSolver(NonlinearProblem& problem, const DofConstraints& constraints, const Eigen::VectorXd& mass,
                               ExplicitOptions options)
    : problem_(problem), constraints_(constraints), options_(options) {
  if (const std::string why = options_.validate(); !why.empty()) throw std::invalid_argument("explicit scheme: " + why);
  if (!constraints_.finalized()) throw std::logic_error("ExplicitSolver: constraints not finalized");
  if (mass.size() != problem_.num_dofs()) throw std::invalid_argument("ExplicitSolver: mass of another size than the DOFs");
  m_ = Eigen::VectorXd::Zero(constraints_.num_reduced());
  for (int i = 0; i < constraints_.num_dofs(); ++i)
    for (const DofConstraints::Term& t : constraints_.expansion(i)) m_(t.reduced) += t.coefficient * t.coefficient * mass(i);
  for (Eigen::Index j = 0; j < m_.size(); ++j)
    if (!(m_(j) > 0.0)) throw std::invalid_argument("ExplicitSolver: reduced unknown " + std::to_string(j) + " has no mass");
  v_ = a_ = Eigen::VectorXd::Zero(m_.size());
  prescribed_rate_ = constraints_.prescribed_values(1.0);  // prescribed values are amplitude x load factor
  moves_prescribed_ = prescribed_rate_.cwiseAbs().maxCoeff() > 0.0;
  re_.resize(problem_.element_dofs().size());
  ev_.resize(re_.size());
}

bool ExplicitSolver::residual(double lambda, Eigen::VectorXd* r, ElementEvaluation* failure) {
  const auto& dofs = problem_.element_dofs();
  const long ne = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (long e = 0; e < ne; ++e) ev_[static_cast<std::size_t>(e)] = problem_.evaluate_element(static_cast<int>(e), &re_[static_cast<std::size_t>(e)], nullptr);
  Eigen::VectorXd full = -problem_.external_forces(lambda);
  for (std::size_t e = 0; e < dofs.size(); ++e) {  // in element order: the same sums for any thread count
    if (!ev_[e].ok) {
      *failure = ev_[e];
      return false;
    }
    for (std::size_t a = 0; a < dofs[e].size(); ++a) full(dofs[e][a]) += re_[e](static_cast<Eigen::Index>(a));
  }
  *r = constraints_.reduce(full);
  return true;
}

bool ExplicitSolver::step(double dt, double lambda0, double lambda1, ElementEvaluation* failure) {
  const Eigen::VectorXd vh = v_ + 0.5 * dt * a_;
  Eigen::VectorXd du = constraints_.expand(dt * vh);
  if (moves_prescribed_ && lambda1 != lambda0) du += (lambda1 - lambda0) * prescribed_rate_;
  problem_.begin_increment(lambda0, lambda1);
  problem_.set_trial(du, 1.0);
  Eigen::VectorXd r;
  if (!residual(lambda1, &r, failure)) {
    problem_.revert();
    return false;
  }
  problem_.accept_trial();
  problem_.commit(lambda1);
  a_ = -r.cwiseQuotient(m_) - options_.damping * vh;
  if (contact_) {
    const Eigen::VectorXd next = dt * (vh + dt * a_);  // the next step's increment without contact forces
    a_ += constraints_.reduce(contact_(dt, lambda1 + (lambda1 - lambda0), next)).cwiseQuotient(m_);
  }
  v_ = vh + 0.5 * dt * a_;
  damping_work_ += dt * options_.damping * vh.dot(m_.cwiseProduct(vh));
  return true;
}

bool ExplicitSolver::start(double lambda, ElementEvaluation* failure) {
  problem_.revert();
  problem_.begin_increment(lambda, lambda);
  Eigen::VectorXd r;
  const bool ok = residual(lambda, &r, failure);
  problem_.revert();
  if (ok) a_ = -r.cwiseQuotient(m_) - options_.damping * v_;
  return ok;
}

bool ExplicitSolver::quarter_steps(double dt, double lambda0, double lambda1, const AfterStep& after_step, double* time, double* reached,
                                   ElementEvaluation* failure) {
  for (int k = 1; k <= 4; ++k) {
    const double lk = k == 4 ? lambda1 : lambda0 + (lambda1 - lambda0) * k / 4.0;
    if (!step(0.25 * dt, *reached, lk, failure)) return false;
    *reached = lk;
    *time += 0.25 * dt;
    if (after_step) after_step(0.25 * dt);
  }
  return true;
}

std::string ExplicitSolver::non_finite_dof() const {
  Eigen::Index j = 0;
  while (j < a_.size() && std::isfinite(a_(j))) ++j;
  for (int dof = 0; dof < constraints_.num_dofs(); ++dof)
    for (const DofConstraints::Term& t : constraints_.expansion(dof))
      if (t.reduced == j) return problem_.describe_dof(dof);
  return "reduced unknown " + std::to_string(j);
}

ExplicitSummary ExplicitSolver::run(const ExplicitSchedule& s, const StepBound& bound, const AfterStep& after_step, const Callback& callback) {
  ExplicitSummary out;
  out.lambda = s.lambda_start;
  if (!(s.duration > 0.0 && s.output_interval > 0.0 && s.lambda_end > s.lambda_start)) {
    out.message = "explicit schedule: need duration > 0, output_interval > 0 and lambda_end > lambda_start";
    return out;
  }
  ElementEvaluation failure;
  if (!start(s.lambda_start, &failure)) {
    out.message = "at the start: " + failure.where + ": " + failure.reason;
    return out;
  }
  double lambda = s.lambda_start, dt_bound = bound();
  out.min_step = out.max_step = 0.0;
  int index = 0;
  for (double point : output_points(s)) {
    ExplicitInterval iv;
    iv.lambda_before = lambda;
    while (lambda < point) {
      const double remaining = (point - lambda) * s.duration;
      const double n = std::max(1.0, std::ceil(remaining / dt_bound * (1.0 - 1e-12)));
      const double dt = remaining / n;
      const double lambda1 = n == 1.0 ? point : lambda + (point - lambda) / n;
      double taken = dt;  // the step size taken (a quarter when cut)
      if (!step(dt, lambda, lambda1, &failure)) {
        taken = 0.25 * dt;
        ++out.cut_steps;
        double reached = lambda;
        if (!quarter_steps(dt, lambda, lambda1, after_step, &out.time, &reached, &failure)) {
          char buf[200];
          std::snprintf(buf, sizeof buf, "step %ld at time %.6g s (load factor %.6g), also cut to a quarter: ", out.steps + 1, out.time, reached);
          out.message = buf + failure.where + ": " + failure.reason;
          out.lambda = reached;
          return out;
        }
      } else {
        out.time += dt;
        if (after_step) after_step(dt);
      }
      lambda = lambda1;
      ++out.steps;
      ++iv.steps;
      iv.time_step = taken;
      out.min_step = out.min_step == 0.0 ? taken : std::min(out.min_step, taken);
      out.max_step = std::max(out.max_step, taken);
      if (!a_.allFinite()) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "step %ld at time %.6g s (load factor %.6g): the acceleration is not finite at ", out.steps, out.time, lambda);
        out.message = buf + non_finite_dof() + " (unstable: a smaller time_step_safety or more mass scaling)";
        out.lambda = lambda;
        return out;
      }
      if (out.steps % options_.recheck_every == 0) dt_bound = bound();
    }
    out.lambda = lambda;
    iv.index = ++index;
    iv.lambda = lambda;
    iv.total_steps = out.steps;
    iv.time = out.time;
    iv.kinetic = kinetic_energy();
    iv.damping_work = damping_work_;
    if (callback && !callback(iv)) return out;
  }
  out.completed = true;
  return out;
}

}  // namespace spifit::solver
