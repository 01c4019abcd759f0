#pragma once
// Exact rotation of a nodal director by a rotation vector (Rodrigues' formula): the
// multiplicative update d <- R(dpsi) d of the shell's rotational DOFs (shell_q4.hpp).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace spifit::element {

inline Eigen::Vector3d rotate_by_vector(const Eigen::Vector3d& v, const Eigen::Vector3d& psi) {
  const double angle = psi.norm();
  if (angle < 1e-300) return v;
  return Eigen::AngleAxisd(angle, psi / angle) * v;
}

}  // namespace spifit::element
