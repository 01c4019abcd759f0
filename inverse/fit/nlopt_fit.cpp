#include "inverse/fit/nlopt_fit.hpp"

#include "inverse/fit/fit_algorithms.hpp"
#include "inverse/fit/solution_analysis.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace spifit::inverse {

namespace {

struct Objective {
  const FitProblem* problem;
  FitProgress* progress = nullptr;
  long evaluations = 0, failures = 0;
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  std::vector<double> history;  // best cost after each evaluation that improved it
};

double objective(unsigned n, const double* x, double* grad, void* data) {
  auto* o = static_cast<Objective*>(data);
  if (grad) for (unsigned i = 0; i < n; ++i) grad[i] = 0.0;  // derivative-free algorithms only
  ++o->evaluations;
  Eigen::VectorXd r;
  const std::vector<double> xv(x, x + n);
  double cost = kFailedRunCost;
  if (evaluate_residuals(*o->problem, xv, &r) && r.allFinite()) cost = 0.5 * r.squaredNorm();
  else ++o->failures;
  if (cost < o->best) {
    o->best = cost;
    o->best_x = xv;
    o->history.push_back(cost);
  }
  if (o->progress) o->progress->iteration_finished(static_cast<int>(o->evaluations), o->best);
  return cost;
}

}  // namespace

FitResult fit_with_nlopt(const FitProblem& fp, const FitRunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const ParameterSet& ps = *fp.parameters;
  const unsigned p = static_cast<unsigned>(ps.num_free());
  FitResult out;
  out.algorithm = options.algorithm.empty() ? fp.settings.algorithm : options.algorithm;
  out.seed = options.seed;
  const FitAlgorithm* found = find_fit_algorithm(out.algorithm);
  if (!found || found->engine != FitAlgorithm::Engine::nlopt) throw std::invalid_argument("not an NLopt algorithm: " + out.algorithm);
  const nlopt::algorithm algorithm = static_cast<nlopt::algorithm>(found->nlopt_code);

  std::vector<double> x = ps.initial_internal();
  for (unsigned k = 0; k < p; ++k) out.initial.push_back(ps.to_physical(static_cast<int>(k), x[k]));
  const auto lo = ps.lower_internal(), hi = ps.upper_internal();
  nlopt::srand(options.seed);
  nlopt::opt opt(algorithm, p);
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  std::vector<double> step(p);
  for (unsigned k = 0; k < p; ++k) step[k] = 0.1 * (hi[k] - lo[k]);
  opt.set_initial_step(step);
  opt.set_xtol_rel(fp.settings.parameter_tolerance);
  opt.set_ftol_rel(fp.settings.function_tolerance);
  const int max_eval = static_cast<int>(std::clamp(50L * fp.settings.max_iterations * static_cast<long>(p), 200L, 100000000L));
  opt.set_maxeval(max_eval);
  nlopt::opt local(nlopt::LN_BOBYQA, p);
  if (algorithm == nlopt::G_MLSL_LDS) {
    local.set_xtol_rel(fp.settings.parameter_tolerance);
    local.set_ftol_rel(fp.settings.function_tolerance);
    local.set_maxeval(max_eval / 10);
    opt.set_local_optimizer(local);
  }
  if (algorithm == nlopt::GN_ISRES || algorithm == nlopt::GN_CRS2_LM) opt.set_population(0);
  Objective obj{&fp, options.progress.get(), 0, 0, std::numeric_limits<double>::infinity(), {}, {}};
  opt.set_min_objective(objective, &obj);
  Eigen::VectorXd r0;
  out.cost_initial = evaluate_residuals(fp, x, &r0) ? 0.5 * r0.squaredNorm() : kFailedRunCost;
  std::string message;
  try {
    double f = 0.0;
    const nlopt::result res = opt.optimize(x, f);
    switch (res) {
      case nlopt::SUCCESS: message = "SUCCESS"; break;
      case nlopt::STOPVAL_REACHED: message = "stop value reached"; break;
      case nlopt::FTOL_REACHED: message = "CONVERGENCE: relative cost tolerance reached"; break;
      case nlopt::XTOL_REACHED: message = "CONVERGENCE: relative parameter tolerance reached"; break;
      case nlopt::MAXEVAL_REACHED: message = "NO_CONVERGENCE: evaluation budget (" + std::to_string(max_eval) + ") used"; break;
      case nlopt::MAXTIME_REACHED: message = "NO_CONVERGENCE: time limit"; break;
      default: message = "NLopt result " + std::to_string(int(res)); break;
    }
  } catch (const nlopt::roundoff_limited&) {
    message = "CONVERGENCE: NLopt stopped on round-off (best point kept)";
  } catch (const std::exception& e) {
    message = std::string("NLopt stopped: ") + e.what() + " (best point kept)";
  }
  if (!obj.best_x.empty()) x = obj.best_x;  // the best point seen, whatever NLopt returned
  out.usable = !obj.best_x.empty() && obj.best < kFailedRunCost;
  out.termination = message + "; " + std::to_string(obj.failures) + " failed forward runs";
  out.cost_final = obj.best;
  out.iterations = static_cast<int>(obj.evaluations);
  out.cost_history = obj.history;
  out.forward_runs = obj.evaluations * static_cast<long>(fp.experiments.size());
  analyse_solution(fp, x, options.threads, &out);
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace spifit::inverse
