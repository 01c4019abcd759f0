#pragma once
// Uncertainty and identifiability of a least-squares fit (docs/design/identification.md): covariance
// sigma^2 (J^T J)^+ with sigma^2 = SSE / (m - p), from a dense SVD of the Jacobian scaled by
// the parameter magnitudes, so that a rank-deficient Jacobian is reported, not crashed on.
#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace spifit::inverse {

struct Uncertainty {
  int m = 0, p = 0, dof = 0;
  double sse = 0.0, sigma2 = 0.0;
  std::vector<double> std_error;          // physical units; +inf where not identifiable
  std::vector<double> ci95_lower, ci95_upper;
  double t_quantile = 0.0;                // Student t(0.975, dof)
  Eigen::MatrixXd covariance, correlation;
  std::vector<double> singular_values;    // of J diag(|value|) (relative sensitivities)
  double condition_number = 0.0;
  std::vector<bool> identifiable;
  std::vector<std::string> warnings;      // plain words
  // The relative offset at the solution over the parameters inside their bounds
  // (inverse/fit/relative_offset.hpp; NaN where it says nothing), and the Gauss-Newton step it
  // bounds in standard errors: how far the optimiser stopped from the least-squares solution.
  double relative_offset = std::numeric_limits<double>::quiet_NaN();
  double offset_step_bound = std::numeric_limits<double>::quiet_NaN();
};

// J: m x p Jacobian of the conditioned residuals w.r.t. the physical parameter values.
// sigma2_without_dof: variance used when m <= p (e.g. 1 when the residuals are conditioned by
// a stated measurement noise); NaN (default) gives no uncertainty then.
Uncertainty analyse_uncertainty(const Eigen::MatrixXd& J, const Eigen::VectorXd& residuals, const std::vector<double>& values,
                                const std::vector<std::string>& names, double sigma2_without_dof = std::numeric_limits<double>::quiet_NaN());

// Which block of rows informs which parameter (docs/design/identification.md, "Which experiment informs
// which parameter"): entry (e, k) is block e's share of parameter k's Fisher information,
// diag(J_eᵀ J_e)_k / diag(Jᵀ J)_k, where J_e are the rows[e] rows of block e (blocks in order).
// A column's shares add up to 1; NaN where no row responds to the parameter.
Eigen::MatrixXd information_shares(const Eigen::MatrixXd& J, const std::vector<int>& rows);

// Quantile of Student's t distribution (two-sided intervals use p = 0.975).
double student_t_quantile(double p, int dof);

}  // namespace spifit::inverse
