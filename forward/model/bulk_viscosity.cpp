#include "forward/model/bulk_viscosity.hpp"

#include "forward/model/explicit_mass.hpp"
#include "forward/model/shell_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spifit::model {

double diagonal_area(const element::NodeVectors& x, element::NodeVectors* gradient) {
  const Eigen::Vector3d d1 = x[2] - x[0], d2 = x[3] - x[1];
  const Eigen::Vector3d cross = d1.cross(d2);
  const double twice = cross.norm();
  if (gradient) {
    // dA = n . (dd1 x d2 + d1 x dd2) / 2 with n the unit normal: dd1 . (d2 x n) + dd2 . (n x d1).
    const Eigen::Vector3d n = twice > 0.0 ? Eigen::Vector3d(cross / twice) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d g1 = 0.5 * d2.cross(n), g2 = 0.5 * n.cross(d1);
    *gradient = {-g1, -g2, g1, g2};
  }
  return 0.5 * twice;
}

double characteristic_length(const element::NodeVectors& x, double area) {
  return area / std::max((x[2] - x[0]).norm(), (x[3] - x[1]).norm());
}

double damped_step_fraction(double xi) { return std::sqrt(1.0 + xi * xi) - xi; }

BulkViscosity::BulkViscosity(const ShellModel& model, const solver::DofConstraints& constraints, std::vector<double> density,
                             std::vector<double> wave_speed, double linear, double quadratic)
    : model_(model),
      constraints_(constraints),
      density_(std::move(density)),
      wave_speed_(std::move(wave_speed)),
      linear_(linear),
      quadratic_(quadratic),
      rate_(static_cast<std::size_t>(model.num_elements()), 0.0) {
  const auto ne = static_cast<std::size_t>(model.num_elements());
  if (density_.size() != ne || wave_speed_.size() != ne) throw std::invalid_argument("BulkViscosity: per-element data of another size than the model");
}

double BulkViscosity::stress(int e, double rate, double length) const {
  const auto k = static_cast<std::size_t>(e);
  const double quadratic = rate < 0.0 ? quadratic_ * quadratic_ * length * rate * std::abs(rate) : 0.0;
  return density_[k] * length * (linear_ * wave_speed_[k] * rate + quadratic);
}

double BulkViscosity::compression_fraction(int e) const {
  const auto k = static_cast<std::size_t>(e);
  if (!(rate_[k] < 0.0) || quadratic_ == 0.0) return 1.0;
  const double xi = linear_ + quadratic_ * quadratic_ * element_length(model_, e) * -rate_[k] / wave_speed_[k];
  return damped_step_fraction(xi) / damped_step_fraction(linear_);
}

Eigen::VectorXd BulkViscosity::forces(const Eigen::VectorXd& v) {
  const Eigen::VectorXd v_full = constraints_.expand(v);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model_.num_dofs());
  const auto& x = model_.positions();
  for (int e = 0; e < model_.num_elements(); ++e) {
    const auto& q = model_.mesh().quads[static_cast<std::size_t>(e)];
    element::NodeVectors corners, gradient;
    for (std::size_t a = 0; a < 4; ++a) corners[a] = x[static_cast<std::size_t>(q[a])];
    const double area = diagonal_area(corners, &gradient);
    double area_rate = 0.0;
    for (std::size_t a = 0; a < 4; ++a) area_rate += gradient[a].dot(v_full.segment<3>(ShellModel::dof(q[a], 0)));
    const double rate = area > 0.0 ? area_rate / area : 0.0;
    rate_[static_cast<std::size_t>(e)] = rate;
    if (rate == 0.0) continue;
    const double resultant = stress(e, rate, characteristic_length(corners, area)) * model_.element_thickness(e);  // in-plane force per length [N/mm]
    for (std::size_t a = 0; a < 4; ++a) f.segment<3>(ShellModel::dof(q[a], 0)) += resultant * gradient[a];
  }
  return f;
}

}  // namespace spifit::model
