#include "inverse/fit/numeric_cost.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace spifit::inverse {

NumericDiffExperimentCost::NumericDiffExperimentCost(const ParameterSet* ps, const Experiment* e, std::atomic<long>* runs,
                                                     double relative_step)
    : ps_(ps), e_(e), runs_(runs), rel_(relative_step), lo_(ps->lower_internal()), hi_(ps->upper_internal()) {
  set_num_residuals(e->num_residuals());
  mutable_parameter_block_sizes()->push_back(ps->num_free());
}

bool NumericDiffExperimentCost::Evaluate(double const* const* xs, double* residuals, double** jacobians) const {
  const int p = ps_->num_free();
  const int m = num_residuals();
  const double* x = xs[0];
  runs_->fetch_add(1, std::memory_order_relaxed);
  if (!e_->residuals(ps_->point(x), residuals)) return false;
  if (!jacobians || !jacobians[0]) return true;
  // Steps inside the bounds: central where possible, one-sided at a bound.
  std::vector<double> xp(p), xm(p), hp(p), hm(p);
  for (int k = 0; k < p; ++k) {
    const double h = rel_ * std::max(std::abs(x[k]), 1e-3 * (hi_[k] - lo_[k]));
    xp[k] = std::min(x[k] + h, hi_[k]);
    xm[k] = std::max(x[k] - h, lo_[k]);
    hp[k] = xp[k] - x[k];
    hm[k] = x[k] - xm[k];
  }
  std::vector<std::vector<double>> rp(p, std::vector<double>(m)), rm(p, std::vector<double>(m));
  std::vector<char> okp(p, 1), okm(p, 1);
  // With a pool of worker processes, as many runs at once as it has workers.
  const int width = std::max(omp_get_max_threads(), e_->parallel_evaluations());
#pragma omp parallel for schedule(dynamic) num_threads(width)
  for (int job = 0; job < 2 * p; ++job) {
    const int k = job / 2;
    const bool plus = job % 2 == 0;
    if ((plus ? hp[k] : hm[k]) == 0.0) continue;
    std::vector<double> y(x, x + p);
    y[k] = plus ? xp[k] : xm[k];
    runs_->fetch_add(1, std::memory_order_relaxed);
    const bool ok = e_->residuals(ps_->point(y.data()), plus ? rp[k].data() : rm[k].data());
    (plus ? okp : okm)[k] = ok ? 1 : 0;
  }
  for (int k = 0; k < p; ++k) {
    const bool has_p = hp[k] > 0 && okp[k], has_m = hm[k] > 0 && okm[k];
    for (int i = 0; i < m; ++i) {
      double d = 0.0;
      if (has_p && has_m) d = (rp[k][i] - rm[k][i]) / (hp[k] + hm[k]);
      else if (has_p) d = (rp[k][i] - residuals[i]) / hp[k];
      else if (has_m) d = (residuals[i] - rm[k][i]) / hm[k];
      else return false;  // no usable perturbation for this parameter
      jacobians[0][i * p + k] = d;
    }
  }
  return true;
}

}  // namespace spifit::inverse
