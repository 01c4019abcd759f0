#pragma once
// What every fit engine does at its solution (docs/design/identification.md, "Uncertainty"): values,
// card, the Jacobian-based uncertainty and the per-experiment costs; and the conditioned
// residuals at a parameter vector.
#include "inverse/fit/fit_result.hpp"
#include "inverse/fit/relative_offset.hpp"

#include <Eigen/Core>

#include <atomic>
#include <vector>

namespace spifit::inverse {

// Fills values, card, Jacobian-based uncertainty and per-experiment costs at the internal
// point x (shared by the Ceres and NLopt drivers).
void analyse_solution(const FitProblem& problem, const std::vector<double>& x, int threads, FitResult* out);

// The relative offset over the free parameters inside their bounds (values: physical; J: the
// Jacobian's columns in the free parameters' order, any scaling): one held at a bound stays
// there, and the step would leave the box.
RelativeOffset offset_inside_bounds(const ParameterSet& ps, const std::vector<double>& values, const Eigen::MatrixXd& J, const Eigen::VectorXd& r);

// The conditioned residuals and their Jacobian in the internal parameters at x, stacked over the
// experiments in fit order, evaluated by Ceres with `threads` threads (an FE experiment's point
// comes from SceneRuns' cache when it was run); each experiment's evaluation counts in
// `evaluations`. False: a forward run failed.
bool stacked_jacobian(const FitProblem& problem, const std::vector<double>& x, int threads, std::atomic<long>* evaluations, Eigen::MatrixXd* J,
                      Eigen::VectorXd* r);

// Conditioned residuals at an internal parameter vector (false: a forward run failed).
bool evaluate_residuals(const FitProblem& problem, const std::vector<double>& internal, Eigen::VectorXd* residuals);

}  // namespace spifit::inverse
