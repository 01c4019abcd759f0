#include "forward/model/material_axes.hpp"

#include <cmath>

namespace spifit::model {

Eigen::Vector3d polar_material_axis(const Eigen::Vector3d& c, const Eigen::Vector3d& a) {
  const double r = std::hypot(c.x(), c.y());
  if (!(r > 1e-12 * (1.0 + c.norm()))) return a;
  const Eigen::Vector3d er(c.x() / r, c.y() / r, 0.0), et(-er.y(), er.x(), 0.0);
  return a.x() * er + a.y() * et + a.z() * Eigen::Vector3d::UnitZ();
}

}  // namespace spifit::model
