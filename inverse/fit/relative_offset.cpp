#include "inverse/fit/relative_offset.hpp"

#include <Eigen/QR>

#include <cmath>

namespace spifit::inverse {

RelativeOffset relative_offset(const Eigen::MatrixXd& J, const Eigen::VectorXd& r) {
  RelativeOffset out;
  if (J.rows() != r.size() || !J.allFinite() || !r.allFinite()) return out;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
  const Eigen::Index rank = qr.rank();
  const Eigen::Index m = J.rows();
  out.rank = static_cast<int>(rank);
  if (rank == 0 || m <= rank) return out;
  const Eigen::VectorXd qtr = qr.householderQ().transpose() * r;
  // A residual in the tangent plane up to round-off, or residuals that are themselves round-off
  // (an exact fit of noise-free data), have no scatter to compare with: there both parts are noise.
  const double along = qtr.head(rank).squaredNorm() / static_cast<double>(rank);
  const double across = qtr.tail(m - rank).squaredNorm() / static_cast<double>(m - rank);
  if (!(qtr.tail(m - rank).norm() > 1e-12 * r.norm()) || !(std::sqrt(across) > kMinimumScatter)) return out;
  out.offset = std::sqrt(along / across);
  return out;
}

double RelativeOffset::step_bound() const { return std::sqrt(static_cast<double>(rank)) * offset; }

}  // namespace spifit::inverse
