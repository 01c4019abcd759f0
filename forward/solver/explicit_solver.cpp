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
  state_.v = state_.a = Eigen::VectorXd::Zero(m_.size());
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
  Eigen::VectorXd& a = state_.a;
  const Eigen::VectorXd vh = state_.v + 0.5 * dt * a;
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
  a = acceleration(r, vh, dt);
  if (contact_) {
    const Eigen::VectorXd next = dt * (vh + dt * a);  // the next step's increment without contact forces
    a += constraints_.reduce(contact_(dt, lambda1 + (lambda1 - lambda0), next)).cwiseQuotient(m_);
  }
  state_.v = vh + 0.5 * dt * a;
  return true;
}

Eigen::VectorXd ExplicitSolver::acceleration(const Eigen::VectorXd& r, const Eigen::VectorXd& v, double dt) {
  Eigen::VectorXd f = options_.damping * m_.cwiseProduct(v);
  if (velocity_forces_) f += constraints_.reduce(velocity_forces_(v));
  // The central-difference pairing: a step's force works over half the moves on either side of
  // it, here the last step's force and this one's over this step's move dt v. Paired with the
  // move of its own step only, the work was off by the order of dt: 1e-3 of the energy of a
  // damped breathing mode at 200 steps a period, 5e-4 at 800; paired, 1.3e-6 at 200
  // (BulkViscosity.BreathingModeOfOneElementDecaysAtTheClosedFormDampingRatio).
  if (dt > 0.0) {
    const double last = state_.damping_force.size() == f.size() ? v.dot(state_.damping_force) : 0.0;
    state_.damping_work += 0.5 * dt * (last + v.dot(f));
  }
  state_.damping_force = f;
  return (-r - f).cwiseQuotient(m_);
}

bool ExplicitSolver::start(double lambda, ElementEvaluation* failure) {
  problem_.revert();
  problem_.begin_increment(lambda, lambda);
  Eigen::VectorXd r;
  const bool ok = residual(lambda, &r, failure);
  problem_.revert();
  if (ok) state_.a = acceleration(r, state_.v, 0.0);
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
  while (j < state_.a.size() && std::isfinite(state_.a(j))) ++j;
  for (int dof = 0; dof < constraints_.num_dofs(); ++dof)
    for (const DofConstraints::Term& t : constraints_.expansion(dof))
      if (t.reduced == j) return problem_.describe_dof(dof);
  return "reduced unknown " + std::to_string(j);
}

void ExplicitSolver::restore(ExplicitState state) {
  if (state.v.size() != m_.size() || state.a.size() != m_.size())
    throw std::invalid_argument("ExplicitSolver: a state of " + std::to_string(state.v.size()) + " unknowns, the problem has " +
                                std::to_string(m_.size()));
  state_ = std::move(state);
}

bool ExplicitSolver::begin(double lambda, const StepBound& bound, std::string* message) {
  state_.lambda = lambda;
  ElementEvaluation failure;
  if (!start(lambda, &failure)) {
    *message = "at the start: " + failure.where + ": " + failure.reason;
    return false;
  }
  state_.step_bound = bound();
  state_.started = true;
  return true;
}

bool ExplicitSolver::take_step(double dt, double lambda1, const AfterStep& after_step, double* taken, std::string* message) {
  ExplicitState& st = state_;
  ElementEvaluation failure;
  *taken = dt;
  if (step(dt, st.lambda, lambda1, &failure)) {
    st.time += dt;
    if (after_step) after_step(dt);
  } else {
    *taken = 0.25 * dt;
    ++st.cut_steps;
    double reached = st.lambda;
    if (!quarter_steps(dt, st.lambda, lambda1, after_step, &st.time, &reached, &failure)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "step %ld at time %.6g s (load factor %.6g), also cut to a quarter: ", st.steps + 1, st.time, reached);
      *message = buf + failure.where + ": " + failure.reason;
      st.lambda = reached;
      return false;
    }
  }
  st.lambda = lambda1;
  ++st.steps;
  st.min_step = st.min_step == 0.0 ? *taken : std::min(st.min_step, *taken);
  st.max_step = std::max(st.max_step, *taken);
  return true;
}

bool ExplicitSolver::advance(double point, double duration, const StepBound& bound, const AfterStep& after_step, ExplicitInterval* iv,
                             std::string* message) {
  ExplicitState& st = state_;
  iv->lambda_before = st.lambda;
  while (st.lambda < point) {
    const double remaining = (point - st.lambda) * duration;
    const double n = std::max(1.0, std::ceil(remaining / st.step_bound * (1.0 - 1e-12)));
    const double lambda1 = n == 1.0 ? point : st.lambda + (point - st.lambda) / n;
    double taken = 0.0;
    if (!take_step(remaining / n, lambda1, after_step, &taken, message)) return false;
    ++iv->steps;
    iv->time_step = taken;
    if (!st.a.allFinite()) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "step %ld at time %.6g s (load factor %.6g): the acceleration is not finite at ", st.steps, st.time, st.lambda);
      *message = buf + non_finite_dof() + " (unstable: a smaller time_step_safety or more mass scaling)";
      return false;
    }
    if (st.steps % options_.recheck_every == 0) st.step_bound = bound();
  }
  iv->index = ++st.outputs;
  iv->lambda = st.lambda;
  iv->total_steps = st.steps;
  iv->time = st.time;
  iv->kinetic = kinetic_energy();
  iv->damping_work = st.damping_work;
  return true;
}

ExplicitSummary ExplicitSolver::summary(bool completed, std::string message) const {
  ExplicitSummary out;
  out.completed = completed;
  out.lambda = state_.lambda;
  out.message = std::move(message);
  out.steps = state_.steps;
  out.cut_steps = state_.cut_steps;
  out.time = state_.time;
  out.min_step = state_.min_step;
  out.max_step = state_.max_step;
  return out;
}

ExplicitSummary ExplicitSolver::run(const ExplicitSchedule& s, const StepBound& bound, const AfterStep& after_step, const Callback& callback) {
  if (!(s.duration > 0.0 && s.output_interval > 0.0 && s.lambda_end > s.lambda_start)) {
    ExplicitSummary out;
    out.lambda = s.lambda_start;
    out.message = "explicit schedule: need duration > 0, output_interval > 0 and lambda_end > lambda_start";
    return out;
  }
  std::string message;
  if (!state_.started && !begin(s.lambda_start, bound, &message)) return summary(false, message);
  for (double point : output_points(s)) {
    if (point <= state_.lambda) continue;  // passed before the checkpoint a restored run starts from
    ExplicitInterval iv;
    if (!advance(point, s.duration, bound, after_step, &iv, &message)) return summary(false, message);
    if (callback && !callback(iv)) return summary(false, "");
  }
  return summary(true, "");
}

}  // namespace spifit::solver
