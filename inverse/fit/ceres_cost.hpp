#pragma once
// The Ceres cost function of one experiment: exact derivatives through Jets where the
// experiment supports them, through the FE runs where they carry sensitivities (exact_cost.hpp),
// central differences (numeric_cost.hpp) for black boxes. Shared by
// the Ceres fit and the analysis at any engine's solution. `runs` counts the forward runs.
#include "inverse/experiments/experiment.hpp"
#include "inverse/fit/parameters.hpp"

#include <ceres/ceres.h>

#include <atomic>

namespace spifit::inverse {

// Owned by the ceres::Problem it is added to.
ceres::CostFunction* make_experiment_cost(const ParameterSet& ps, const Experiment& e, std::atomic<long>* runs);

}  // namespace spifit::inverse
