#pragma once
// Central-difference Jacobian for black-box experiments (FE scenes: no Jets). The 2p perturbed
// forward runs are evaluated in parallel (OpenMP) and never leave the bounds: at a bound the
// difference becomes one-sided. Step: h_k = relative_step * max(|x_k|, 1e-3 * (upper - lower)).
#include "inverse/experiments/experiment.hpp"
#include "inverse/fit/parameters.hpp"

#include <ceres/cost_function.h>

#include <atomic>

namespace spifit::inverse {

class NumericDiffExperimentCost final : public ceres::CostFunction {
 public:
  NumericDiffExperimentCost(const ParameterSet* parameters, const Experiment* experiment, std::atomic<long>* runs,
                            double relative_step = 1e-6);
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

 private:
  const ParameterSet* ps_;
  const Experiment* e_;
  std::atomic<long>* runs_;
  double rel_;
  std::vector<double> lo_, hi_;
};

}  // namespace spifit::inverse
