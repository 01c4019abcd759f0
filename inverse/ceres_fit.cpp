#include "inverse/ceres_fit.hpp"

#include "forward/io/input_error.hpp"
#include "inverse/numeric_cost.hpp"

#include <ceres/ceres.h>

#include <atomic>
#include <chrono>

namespace spifit::inverse {

namespace {

// One residual block per experiment; Ceres differentiates with Jet<double, kJetSize>.
struct ExperimentFunctor {
  const ParameterSet* parameters;
  const Experiment* experiment;
  std::atomic<long>* runs;
  template <typename T>
  bool operator()(T const* const* x, T* r) const {
    runs->fetch_add(1, std::memory_order_relaxed);
    const auto m = parameters->apply(x[0]);
    return experiment->residuals(m, r);
  }
};

// Exact derivatives through Jets where the experiment supports them, central differences
// (parallel, inside the bounds) for black boxes.
ceres::CostFunction* make_cost(const ParameterSet& ps, const Experiment& e, std::atomic<long>* runs) {
  if (!e.supports_jets()) return new NumericDiffExperimentCost(&ps, &e, runs);
  auto* cf = new ceres::DynamicAutoDiffCostFunction<ExperimentFunctor, kJetSize>(new ExperimentFunctor{&ps, &e, runs});
  cf->AddParameterBlock(ps.num_free());
  cf->SetNumResiduals(e.num_residuals());
  return cf;
}

class CostHistory final : public ceres::IterationCallback {
 public:
  explicit CostHistory(std::vector<double>* h) : h_(h) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    h_->push_back(s.cost);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  std::vector<double>* h_;
};

}  // namespace

bool evaluate_residuals(const FitProblem& fp, const std::vector<double>& internal, Eigen::VectorXd* residuals) {
  const auto m = fp.parameters->apply(internal.data());
  int total = 0;
  for (const auto& e : fp.experiments) total += e->num_residuals();
  residuals->resize(total);
  int offset = 0;
  for (const auto& e : fp.experiments) {
    if (!e->residuals(m, residuals->data() + offset)) return false;
    offset += e->num_residuals();
  }
  return true;
}

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
  for (const auto& e : fp.experiments) problem.AddResidualBlock(make_cost(ps, *e, &runs), nullptr, x.data());
  const auto lo = ps.lower_internal(), hi = ps.upper_internal();
  for (int k = 0; k < p; ++k) {
    problem.SetParameterLowerBound(x.data(), k, lo[k]);
    problem.SetParameterUpperBound(x.data(), k, hi[k]);
  }

  // Each experiment at the start: a failure there is named instead of ending in a bare
  // "evaluation failed".
  {
    const auto m0 = ps.apply(x.data());
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
  CostHistory history(&out.cost_history);
  so.callbacks.push_back(&history);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  out.termination = ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
  out.usable = summary.IsSolutionUsable();
  out.iterations = static_cast<int>(summary.iterations.size());
  out.cost_final = summary.final_cost;

  analyse_solution(fp, x, so.num_threads, &out);
  out.forward_runs += runs.load();
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

void analyse_solution(const FitProblem& fp, const std::vector<double>& x_in, int threads, FitResult* out_ptr) {
  FitResult& out = *out_ptr;
  const ParameterSet& ps = *fp.parameters;
  const int p = ps.num_free();
  std::vector<double> x = x_in;
  out.values.clear();
  for (int k = 0; k < p; ++k) out.values.push_back(ps.to_physical(k, x[k]));
  out.card = ps.card_for(x);
  try {
    material::validate_material_card(out.card);
  } catch (const io::InputError& e) {
    out.usable = false;
    out.uncertainty.warnings.push_back(std::string("the fitted card is not valid: ") + e.key() + " = " + e.value() + ": " + e.message());
  }
  std::atomic<long> runs{0};
  ceres::Problem::Options popts;
  popts.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(popts);
  for (const auto& e : fp.experiments) problem.AddResidualBlock(make_cost(ps, *e, &runs), nullptr, x.data());
  ceres::Problem::EvaluateOptions eo;
  eo.num_threads = std::max(1, threads);
  double cost = 0.0;
  std::vector<double> res;
  ceres::CRSMatrix crs;
  if (problem.Evaluate(eo, &cost, &res, nullptr, &crs)) {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
    for (int i = 0; i < crs.num_rows; ++i) {
      for (int j = crs.rows[i]; j < crs.rows[i + 1]; ++j) J(i, crs.cols[j]) = crs.values[j];
    }
    for (int k = 0; k < p; ++k) J.col(k) /= ps.physical_per_internal(k, x[k]);
    const Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(res.data(), static_cast<Eigen::Index>(res.size()));
    std::vector<std::string> names;
    for (int idx : ps.free_indices()) names.push_back(ps.specs()[idx].name);
    bool known_noise = true;
    for (const auto& e : fp.experiments) known_noise = known_noise && e->noise_given();
    out.uncertainty = analyse_uncertainty(J, r, out.values, names, known_noise ? 1.0 : std::numeric_limits<double>::quiet_NaN());
    auto& u = out.uncertainty;
    for (int k = 0; k < p; ++k) {
      const auto& spec = ps.specs()[ps.free_indices()[k]];
      // Log-scaled parameters: the interval is symmetric in ln(value), so it stays positive.
      if (spec.log_scale && std::isfinite(u.std_error[k]) && out.values[k] > 0) {
        const double f = std::exp(u.t_quantile * u.std_error[k] / out.values[k]);
        u.ci95_lower[k] = out.values[k] / f;
        u.ci95_upper[k] = out.values[k] * f;
      }
      const double span = spec.upper - spec.lower;
      if (out.values[k] <= spec.lower + 1e-6 * span || out.values[k] >= spec.upper - 1e-6 * span) {
        u.warnings.push_back(spec.name + " ended at its bound (" + io::format_number(out.values[k]) +
                             "): the data push it further, or it is poorly determined; its interval is not meaningful.");
      }
    }
    out.experiment_costs.clear();
    int offset = 0;
    for (const auto& e : fp.experiments) {
      ExperimentCost ec{e->name(), e->kind(), e->num_residuals(), 0.0, 0.0};
      for (int i = 0; i < ec.points; ++i) ec.cost += 0.5 * r(offset + i) * r(offset + i);
      ec.rms = std::sqrt(2.0 * ec.cost / ec.points);
      offset += ec.points;
      out.experiment_costs.push_back(ec);
    }
  } else {
    out.uncertainty.warnings.push_back("the forward model failed at the solution: no uncertainty estimate");
  }
  out.forward_runs += runs.load();
}

}  // namespace spifit::inverse
