#pragma once
// The cost function of an FE experiment whose runs carry exact derivatives (direct
// differentiation through the FE model, docs/design/sensitivities.md): one forward run per
// point, residuals and Jacobian from it. The experiment's derivatives are with respect to the
// free parameters' physical values; the optimiser's coordinates are internal (the log of a
// log-scaled parameter), so column k is scaled by d physical / d internal.
#include "inverse/experiments/experiment.hpp"
#include "inverse/fit/parameters.hpp"

#include <ceres/cost_function.h>

#include <atomic>

namespace spifit::inverse {

class ExactFeExperimentCost final : public ceres::CostFunction {
 public:
  // experiment->exact_columns() must equal parameters->num_free() (std::logic_error otherwise).
  ExactFeExperimentCost(const ParameterSet* parameters, const Experiment* experiment, std::atomic<long>* runs);
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

 private:
  const ParameterSet* ps_;
  const Experiment* e_;
  std::atomic<long>* runs_;
};

}  // namespace spifit::inverse
