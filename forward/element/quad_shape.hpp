#pragma once
// Bilinear shape functions of the 4-node quadrilateral on (xi, eta) in [-1, 1]^2, nodes
// counter-clockwise from (-1, -1); shared by the shell element, its contact points and the
// consistent nodal loads.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>

namespace spifit::element {

using NodeVectors = std::array<Eigen::Vector3d, 4>;

inline constexpr double kNodeXi[4] = {-1.0, 1.0, 1.0, -1.0};
inline constexpr double kNodeEta[4] = {-1.0, -1.0, 1.0, 1.0};

inline Eigen::Vector4d quad_shape(double xi, double eta) {
  Eigen::Vector4d n;
  for (int i = 0; i < 4; ++i) n(i) = 0.25 * (1.0 + kNodeXi[i] * xi) * (1.0 + kNodeEta[i] * eta);
  return n;
}

// Row 0: d/dxi, row 1: d/deta.
inline Eigen::Matrix<double, 2, 4> quad_shape_derivatives(double xi, double eta) {
  Eigen::Matrix<double, 2, 4> d;
  for (int i = 0; i < 4; ++i) {
    d(0, i) = 0.25 * kNodeXi[i] * (1.0 + kNodeEta[i] * eta);
    d(1, i) = 0.25 * kNodeEta[i] * (1.0 + kNodeXi[i] * xi);
  }
  return d;
}

inline Eigen::Vector3d combine(const Eigen::Ref<const Eigen::Vector4d>& w, const NodeVectors& v) {
  return w(0) * v[0] + w(1) * v[1] + w(2) * v[2] + w(3) * v[3];
}

// Area Jacobian |x,xi x x,eta| of the (possibly warped) quad at (xi, eta).
inline double quad_area_jacobian(const NodeVectors& x, double xi, double eta) {
  const Eigen::Matrix<double, 2, 4> d = quad_shape_derivatives(xi, eta);
  return combine(d.row(0).transpose(), x).cross(combine(d.row(1).transpose(), x)).norm();
}

}  // namespace spifit::element
