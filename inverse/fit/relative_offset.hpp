#pragma once
// The relative offset convergence criterion of nonlinear least squares (Bates & Watts 1981;
// docs/design/identification.md, "Stopping"): how far the residual vector r still leans into the
// tangent plane of the model (the column space of the Jacobian J), against the residuals' own
// scatter. With J = Q R and Q = [Q1 Q2] (Q1 spanning J's p columns, Q2 the m - p others),
//
//   offset = (|Q1^T r| / sqrt(p)) / (|Q2^T r| / sqrt(m - p)).
//
// The Gauss-Newton step from here moves parameter k by at most sqrt(p) * offset of its standard
// error (s^2 (R^T R)^-1 with s^2 = |Q2^T r|^2 / (m - p)): a small offset says that the optimiser
// cannot move the parameters by an amount the data could tell apart. Unlike a tolerance on the
// cost, it does not depend on the cost's size, and it is the same in any coordinates of the
// parameters (it depends on the column space of J only).
#include <Eigen/Core>

#include <limits>

namespace spifit::inverse {

// The residuals' scatter |Q2^T r| / sqrt(m - p) below which the criterion says nothing: the
// residuals are conditioned (by a stated noise, or by the range of the measured values), so a
// scatter of 1e-6 is a millionth of the noise, or of the range: an exact fit.
constexpr double kMinimumScatter = 1e-6;

struct RelativeOffset {
  // NaN where the criterion says nothing: no more residuals than J's rank, residuals without
  // scatter (below kMinimumScatter, or in the tangent plane entirely: the model fits the data
  // exactly), or a non-finite J or r.
  double offset = std::numeric_limits<double>::quiet_NaN();
  int rank = 0;  // J's numerical rank (p where the parameters are identifiable)
  // The Gauss-Newton step's bound in standard errors: sqrt(rank) * offset.
  double step_bound() const;
};

// J: m x p Jacobian of the residuals r (any scaling of its columns).
RelativeOffset relative_offset(const Eigen::MatrixXd& J, const Eigen::VectorXd& r);

}  // namespace spifit::inverse
