#include "inverse/fit/exact_cost.hpp"

#include <stdexcept>
#include <vector>

namespace spifit::inverse {

ExactFeExperimentCost::ExactFeExperimentCost(const ParameterSet* ps, const Experiment* e, std::atomic<long>* runs) : ps_(ps), e_(e), runs_(runs) {
  if (e->exact_columns() != ps->num_free())
    throw std::logic_error("experiment " + e->name() + ": exact derivatives with respect to " + std::to_string(e->exact_columns()) +
                           " parameters, the fit has " + std::to_string(ps->num_free()));
  set_num_residuals(e->num_residuals());
  mutable_parameter_block_sizes()->push_back(ps->num_free());
}

bool ExactFeExperimentCost::Evaluate(double const* const* xs, double* residuals, double** jacobians) const {
  const double* x = xs[0];
  runs_->fetch_add(1, std::memory_order_relaxed);
  const ParameterPoint point = ps_->point(x);
  if (!jacobians || !jacobians[0]) return e_->residuals(point, residuals);
  const int p = ps_->num_free(), m = num_residuals();
  std::vector<double> drdp(static_cast<std::size_t>(m) * static_cast<std::size_t>(p));
  if (!e_->residuals_and_derivatives(point, residuals, drdp.data())) return false;
  for (int k = 0; k < p; ++k) {
    const double per = ps_->physical_per_internal(k, x[k]);
    for (int i = 0; i < m; ++i) {
      const std::size_t at = static_cast<std::size_t>(i) * static_cast<std::size_t>(p) + static_cast<std::size_t>(k);
      jacobians[0][at] = drdp[at] * per;
    }
  }
  return true;
}

}  // namespace spifit::inverse
