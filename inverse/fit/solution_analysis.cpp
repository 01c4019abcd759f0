#include "inverse/fit/solution_analysis.hpp"

#include "forward/io/input_error.hpp"
#include "inverse/fit/ceres_cost.hpp"
#include "inverse/fit/fit_assessment.hpp"
#include "inverse/fit/relative_offset.hpp"

#include <ceres/ceres.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>

namespace spifit::inverse {

bool evaluate_residuals(const FitProblem& fp, const std::vector<double>& internal, Eigen::VectorXd* residuals) {
  const ParameterPoint m = fp.parameters->point(internal.data());
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

bool stacked_jacobian(const FitProblem& fp, const std::vector<double>& x_in, int threads, std::atomic<long>* evaluations, Eigen::MatrixXd* J,
                      Eigen::VectorXd* r) {
  std::vector<double> x = x_in;  // the problem's parameter block
  ceres::Problem::Options popts;
  popts.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(popts);
  for (const auto& e : fp.experiments) problem.AddResidualBlock(make_experiment_cost(*fp.parameters, *e, evaluations), nullptr, x.data());
  ceres::Problem::EvaluateOptions eo;
  eo.num_threads = std::max(1, threads);
  double cost = 0.0;
  std::vector<double> res;
  ceres::CRSMatrix crs;
  if (!problem.Evaluate(eo, &cost, &res, nullptr, &crs)) return false;
  *J = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int i = 0; i < crs.num_rows; ++i)
    for (int j = crs.rows[i]; j < crs.rows[i + 1]; ++j) (*J)(i, crs.cols[j]) = crs.values[j];
  *r = Eigen::Map<const Eigen::VectorXd>(res.data(), static_cast<Eigen::Index>(res.size()));
  return true;
}

namespace {

// A step from the solution larger than this many standard errors: the optimiser stopped short.
constexpr double kUnconvergedStep = 0.1;

// The relative offset at the solution over the parameters inside their bounds, with a warning
// where the Gauss-Newton step left would move one of them by more than a tenth of its standard
// error.
void check_convergence(const ParameterSet& ps, const std::vector<double>& values, const Eigen::MatrixXd& J, const Eigen::VectorXd& r,
                       Uncertainty* u) {
  const RelativeOffset o = offset_inside_bounds(ps, values, J, r);
  u->relative_offset = o.offset;
  u->offset_step_bound = o.step_bound();
  if (std::isfinite(o.offset) && o.step_bound() > kUnconvergedStep) {
    char m[320];
    std::snprintf(m, sizeof m,
                  "the optimiser stopped short of the least-squares solution: a Gauss-Newton step from here would still move a parameter by up to "
                  "%.2g standard errors (relative offset %.2g); allow more iterations or tighter tolerances",
                  o.step_bound(), o.offset);
    u->warnings.push_back(m);
  }
}

}  // namespace

RelativeOffset offset_inside_bounds(const ParameterSet& ps, const std::vector<double>& values, const Eigen::MatrixXd& J, const Eigen::VectorXd& r) {
  std::vector<Eigen::Index> inside;
  for (int k = 0; k < ps.num_free(); ++k)
    if (bound_side(ps.specs()[ps.free_indices()[k]], values[k]) == 0) inside.push_back(k);
  if (inside.empty()) return {};
  Eigen::MatrixXd Ji(J.rows(), static_cast<Eigen::Index>(inside.size()));
  for (std::size_t c = 0; c < inside.size(); ++c) Ji.col(static_cast<Eigen::Index>(c)) = J.col(inside[c]);
  return relative_offset(Ji, r);
}

void analyse_solution(const FitProblem& fp, const std::vector<double>& x_in, int threads, FitResult* out_ptr) {
  FitResult& out = *out_ptr;
  const ParameterSet& ps = *fp.parameters;
  const int p = ps.num_free();
  std::vector<double> x = x_in;
  out.values.clear();
  for (int k = 0; k < p; ++k) out.values.push_back(ps.to_physical(k, x[k]));
  out.card = ps.card_for(x);
  std::atomic<long> runs{0};
  Eigen::MatrixXd J;
  Eigen::VectorXd r;
  if (stacked_jacobian(fp, x, threads, &runs, &J, &r)) {
    for (int k = 0; k < p; ++k) J.col(k) /= ps.physical_per_internal(k, x[k]);
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
      if (bound_side(spec, out.values[k]) != 0) {
        u.warnings.push_back(spec.name + " ended at its bound (" + io::format_number(out.values[k]) +
                             "): the data push it further, or it is poorly determined; its interval is not meaningful.");
      }
    }
    check_convergence(ps, out.values, J, r, &u);
    out.experiment_costs.clear();
    std::vector<int> rows;
    for (const auto& e : fp.experiments) rows.push_back(e->num_residuals());
    const Eigen::MatrixXd shares = information_shares(J, rows);
    int offset = 0;
    for (std::size_t n = 0; n < fp.experiments.size(); ++n) {
      const auto& e = fp.experiments[n];
      ExperimentCost ec;
      ec.name = e->name();
      ec.kind = e->kind();
      ec.points = e->num_residuals();
      double noise_ss = 0.0;
      for (int i = 0; i < ec.points; ++i) {
        const double ri = r(offset + i), w = e->residual_weight(i);
        ec.cost += 0.5 * ri * ri;
        if (e->noise_given() && w > 0.0) {
          noise_ss += ri * ri / w;
          ++ec.noise_points;
        }
      }
      ec.rms = std::sqrt(2.0 * ec.cost / ec.points);
      if (ec.noise_points > 0) ec.noise_rms = std::sqrt(noise_ss / ec.noise_points);
      for (int k = 0; k < p; ++k) ec.information_share.push_back(shares(static_cast<Eigen::Index>(n), k));
      offset += ec.points;
      out.experiment_costs.push_back(ec);
    }
  } else {
    out.uncertainty.warnings.push_back("the forward model failed at the solution: no uncertainty estimate");
  }
  out.forward_runs += runs.load();
}

}  // namespace spifit::inverse
