#include "inverse/fit/ceres_fit.hpp"

#include "forward/io/input_error.hpp"
#include "inverse/fit/ceres_cost.hpp"
#include "inverse/fit/relative_offset.hpp"
#include "inverse/fit/solution_analysis.hpp"

#include <ceres/ceres.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

namespace spifit::inverse {

namespace {

// The cost of every iteration, and the iteration to whoever follows the fit's progress.
class CostHistory final : public ceres::IterationCallback {
 public:
  CostHistory(std::vector<double>* h, FitProgress* progress) : h_(h), progress_(progress) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    h_->push_back(s.cost);
    if (progress_) progress_->iteration_finished(s.iteration, s.cost);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  std::vector<double>* h_;
  FitProgress* progress_;
};

// Ends the fit once the relative offset at an accepted point, over the parameters inside their
// bounds, is at most the tolerance (relative_offset.hpp). The residuals and Jacobian at that
// point are those Ceres has just asked for: an FE run is not made again (SceneRuns keeps each
// point's run). Its evaluations count with the fit's (`evaluations`), as the experiments count
// them.
class OffsetStop final : public ceres::IterationCallback {
 public:
  OffsetStop(const FitProblem& fp, const std::vector<double>* x, double tolerance, int threads, std::atomic<long>* evaluations)
      : fp_(fp), x_(x), tolerance_(tolerance), threads_(threads), evaluations_(evaluations) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (s.iteration > 0 && !s.step_is_successful) return ceres::SOLVER_CONTINUE;
    const int p = fp_.parameters->num_free();
    Eigen::MatrixXd J;
    Eigen::VectorXd r;
    if (!stacked_jacobian(fp_, *x_, threads_, evaluations_, &J, &r)) return ceres::SOLVER_CONTINUE;
    std::vector<double> values;
    for (int k = 0; k < p; ++k) values.push_back(fp_.parameters->to_physical(k, (*x_)[static_cast<std::size_t>(k)]));
    last_ = offset_inside_bounds(*fp_.parameters, values, J, r);
    if (!(last_.offset <= tolerance_)) return ceres::SOLVER_CONTINUE;
    stopped_ = true;
    return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
  }
  bool stopped() const { return stopped_; }
  std::string message() const {
    char m[256];
    std::snprintf(m, sizeof m,
                  "CONVERGENCE: relative offset %.3g <= %.3g (the Gauss-Newton step left is below %.2g standard errors of any parameter inside its bounds)",
                  last_.offset, tolerance_, last_.step_bound());
    return m;
  }

 private:
  const FitProblem& fp_;
  const std::vector<double>* x_;
  double tolerance_;
  int threads_;
  std::atomic<long>* evaluations_;
  RelativeOffset last_;
  bool stopped_ = false;
};

}  // namespace

FitResult fit_with_ceres(const FitProblem& fp, const FitRunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const ParameterSet& ps = *fp.parameters;
  const int p = ps.num_free();
  FitResult out;
  out.algorithm = options.algorithm.empty() ? fp.settings.algorithm : options.algorithm;
  std::vector<double> x = ps.initial_internal();
  for (int k = 0; k < p; ++k) out.initial.push_back(ps.to_physical(k, x[k]));
  std::atomic<long> runs{0};

  ceres::Problem::Options popts;
  popts.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(popts);
  for (const auto& e : fp.experiments) problem.AddResidualBlock(make_experiment_cost(ps, *e, &runs), nullptr, x.data());
  const auto lo = ps.lower_internal(), hi = ps.upper_internal();
  for (int k = 0; k < p; ++k) {
    problem.SetParameterLowerBound(x.data(), k, lo[k]);
    problem.SetParameterUpperBound(x.data(), k, hi[k]);
  }

  // Each experiment at the start: a failure there is named instead of ending in a bare
  // "evaluation failed".
  {
    const ParameterPoint m0 = ps.point(x.data());
    for (const auto& e : fp.experiments) {
      std::vector<double> r(e->num_residuals());
      if (!e->residuals(m0, r.data())) {
        out.termination = "FAILURE: experiment " + e->name() + " cannot be simulated at the initial parameters";
        out.usable = false;
        for (int k = 0; k < p; ++k) out.values.push_back(out.initial[k]);
        out.card = ps.card_for(x);
        out.cost_initial = out.cost_final = std::numeric_limits<double>::infinity();
        out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return out;
      }
    }
  }
  double cost0 = 0.0;
  const bool start_ok = problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost0, nullptr, nullptr, nullptr);
  out.cost_initial = start_ok ? cost0 : std::numeric_limits<double>::infinity();

  ceres::Solver::Options so;
  so.trust_region_strategy_type = out.algorithm == "dogleg" ? ceres::DOGLEG : ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = fp.settings.max_iterations;
  so.function_tolerance = fp.settings.function_tolerance;
  so.parameter_tolerance = fp.settings.parameter_tolerance;
  so.gradient_tolerance = fp.settings.gradient_tolerance;
  so.num_threads = std::max(1, options.threads);
  so.logging_type = ceres::SILENT;
  CostHistory history(&out.cost_history, options.progress.get());
  so.callbacks.push_back(&history);
  std::unique_ptr<OffsetStop> offset_stop;
  if (fp.settings.offset_tolerance > 0.0) {
    offset_stop = std::make_unique<OffsetStop>(fp, &x, fp.settings.offset_tolerance, so.num_threads, &runs);
    so.update_state_every_iteration = true;
    so.callbacks.push_back(offset_stop.get());
  }
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  out.termination = ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
  if (offset_stop && offset_stop->stopped()) out.termination = offset_stop->message();
  out.usable = summary.IsSolutionUsable();
  out.iterations = static_cast<int>(summary.iterations.size());
  out.cost_final = summary.final_cost;

  analyse_solution(fp, x, so.num_threads, &out);
  out.forward_runs += runs.load();
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace spifit::inverse
