#include "inverse/uncertainty/uncertainty.hpp"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace spifit::inverse {

namespace {

// Regularised incomplete beta I_x(a, b) by its continued fraction (modified Lentz).
double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double lbeta = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b);
  const double front = std::exp(lbeta + a * std::log(x) + b * std::log1p(-x));
  if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - incomplete_beta(b, a, 1.0 - x);
  constexpr double tiny = 1e-300;
  double f = 1.0, c = 1.0, d = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const int m = i / 2;
    double num;
    if (i == 0) num = 1.0;
    else if (i % 2 == 0) num = (m * (b - m) * x) / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
    else num = -((a + m) * (a + b + m) * x) / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
    d = 1.0 + num * d;
    if (std::abs(d) < tiny) d = tiny;
    d = 1.0 / d;
    c = 1.0 + num / c;
    if (std::abs(c) < tiny) c = tiny;
    const double cd = c * d;
    f *= cd;
    if (std::abs(1.0 - cd) < 1e-15) break;
  }
  return front * (f - 1.0) / a;
}

double student_t_cdf(double t, int dof) {
  const double v = dof;
  const double x = v / (v + t * t);
  const double tail = 0.5 * incomplete_beta(0.5 * v, 0.5, x);
  return t >= 0 ? 1.0 - tail : tail;
}

}  // namespace

double student_t_quantile(double p, int dof) {
  if (dof <= 0) return std::numeric_limits<double>::infinity();
  double lo = -1e3, hi = 1e3;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (student_t_cdf(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Eigen::MatrixXd information_shares(const Eigen::MatrixXd& J, const std::vector<int>& rows) {
  const Eigen::Index p = J.cols();
  Eigen::MatrixXd share(static_cast<Eigen::Index>(rows.size()), p);
  const Eigen::RowVectorXd total = J.colwise().squaredNorm();
  Eigen::Index first = 0;
  for (std::size_t e = 0; e < rows.size(); ++e) {
    const Eigen::RowVectorXd own = J.middleRows(first, rows[e]).colwise().squaredNorm();
    for (Eigen::Index k = 0; k < p; ++k)
      share(static_cast<Eigen::Index>(e), k) = total(k) > 0.0 ? own(k) / total(k) : std::numeric_limits<double>::quiet_NaN();
    first += rows[e];
  }
  return share;
}

Uncertainty analyse_uncertainty(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const std::vector<double>& values,
                                const std::vector<std::string>& names, double sigma2_without_dof) {
  Uncertainty u;
  u.m = static_cast<int>(J.rows());
  u.p = static_cast<int>(J.cols());
  u.dof = u.m - u.p;
  u.sse = r.squaredNorm();
  u.sigma2 = u.dof > 0 ? u.sse / u.dof : sigma2_without_dof;
  // Known variance (no dof): normal quantile, i.e. t with infinitely many dof.
  u.t_quantile = u.dof > 0 ? student_t_quantile(0.975, u.dof) : (std::isfinite(u.sigma2) ? 1.959963984540054 : student_t_quantile(0.975, u.dof));

  // Scale columns by |value| so that singular values compare relative sensitivities.
  Eigen::VectorXd s(u.p);
  for (int k = 0; k < u.p; ++k) s(k) = values[k] != 0.0 ? std::abs(values[k]) : 1.0;
  const Eigen::MatrixXd Js = J * s.asDiagonal();
  // Full V: with fewer residuals than parameters the null space is in the last columns.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  for (int i = 0; i < sv.size(); ++i) u.singular_values.push_back(sv(i));
  const double smax = sv.size() ? sv(0) : 0.0;
  // Relative and absolute floors: residuals are conditioned (noise or range units), so a
  // scaled singular value below 1e-6 means a 100 % change of the parameters moves the fit by
  // a millionth of the noise.
  const double rank_tol = std::max(1e-10 * smax, 1e-6);
  const double smin = sv.size() == u.p ? sv(sv.size() - 1) : 0.0;
  u.condition_number = smin > 0 ? smax / smin : std::numeric_limits<double>::infinity();

  // Pseudo-inverse of Js^T Js on the identifiable subspace; flag parameters that load the
  // (numerically) null directions.
  const Eigen::MatrixXd V = svd.matrixV();
  Eigen::MatrixXd cov_s = Eigen::MatrixXd::Zero(u.p, u.p);
  u.identifiable.assign(u.p, true);
  for (int i = 0; i < u.p; ++i) {
    const double si = i < sv.size() ? sv(i) : 0.0;
    if (si > rank_tol) {
      cov_s += V.col(i) * V.col(i).transpose() / (si * si);
    } else {
      for (int k = 0; k < u.p; ++k) if (std::abs(V(k, i)) > 0.1) u.identifiable[k] = false;
    }
  }
  if (smax == 0.0) u.identifiable.assign(u.p, false);
  const double sigma2 = std::isfinite(u.sigma2) ? u.sigma2 : 0.0;
  u.covariance = sigma2 * s.asDiagonal() * cov_s * s.asDiagonal();
  u.correlation = Eigen::MatrixXd::Identity(u.p, u.p);
  for (int k = 0; k < u.p; ++k) {
    const double se = u.identifiable[k] && std::isfinite(u.sigma2) ? std::sqrt(std::max(u.covariance(k, k), 0.0)) : std::numeric_limits<double>::infinity();
    u.std_error.push_back(se);
    u.ci95_lower.push_back(values[k] - u.t_quantile * se);
    u.ci95_upper.push_back(values[k] + u.t_quantile * se);
  }
  // Correlation does not depend on sigma^2: from the unscaled pseudo-inverse.
  const Eigen::MatrixXd shape = s.asDiagonal() * cov_s * s.asDiagonal();
  for (int a = 0; a < u.p; ++a) {
    for (int b = 0; b < u.p; ++b) {
      const double d = std::sqrt(shape(a, a) * shape(b, b));
      u.correlation(a, b) = (a == b) ? 1.0 : (d > 0 ? shape(a, b) / d : 0.0);
    }
  }
  for (int k = 0; k < u.p; ++k) {
    if (!u.identifiable[k]) {
      const bool flat = Js.col(k).norm() <= rank_tol;  // scaled sensitivity at round-off level
      u.warnings.push_back(names[k] + " is not identifiable from the chosen experiments" +
                           (flat ? std::string(": no experiment responds to it") : std::string(": its effect is indistinguishable from other parameters'")) +
                           "; fix it or add an experiment that depends on it.");
    }
  }
  const bool all_identifiable = std::all_of(u.identifiable.begin(), u.identifiable.end(), [](bool b) { return b; });
  if (u.dof <= 0 && std::isfinite(u.sigma2)) {
    u.warnings.push_back("no more data points than free parameters: intervals assume the stated measurement noise.");
  } else if (u.dof <= 0) {
    u.warnings.push_back("no more data points than free parameters: no residual degrees of freedom, no uncertainty estimate.");
  } else if (all_identifiable && std::isfinite(u.condition_number) && u.condition_number > 1e8) {
    std::ostringstream os;
    os << "the scaled Jacobian is ill-conditioned (condition number " << u.condition_number
       << "): some parameter combinations are poorly determined; see the correlation matrix.";
    u.warnings.push_back(os.str());
  }
  return u;
}

}  // namespace spifit::inverse
