#pragma once
// What the hexahedral element tests share: the Hill card C.3 + C.4, boxes, homogeneous maps of
// corners, a fixed rotation, and the count of zero eigenvalues of a stiffness.
#include "forward/element/hex8_stiffness.hpp"
#include "forward/material/kinematic/kinematic_laws.hpp"
#include "forward/material/material_params.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>

namespace spifit::element::test {

inline material::MaterialParams<double> aa3003() {  // card C.3 + C.4 (Hill 1948 + Swift)
  material::MaterialParams<double> p;
  p.F = 1.224; p.G = 1.193; p.H = 0.807; p.N = p.L = p.M = 4.06;
  return p;
}

// Card C.3 + C.4 with the back-stress of card C.7 (Armstrong-Frederick, App. C.3.2): a consistent
// tangent that is not symmetric.
inline material::MaterialParams<double> aa3003_af() {
  material::MaterialParams<double> p = aa3003();
  p.kinematic = material::make_kinematic<material::ArmstrongFrederick>({51.4, 46.0});
  return p;
}

// The box [0, a] x [0, b] x [0, c] in VTK corner order.
inline HexCorners box(double a, double b, double c) {
  HexCorners X;
  const double s[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int I = 0; I < 8; ++I) X[static_cast<std::size_t>(I)] = Eigen::Vector3d(a * s[I][0], b * s[I][1], c * s[I][2]);
  return X;
}

// x_I = F X_I + c.
inline HexCorners map(const HexCorners& X, const Eigen::Matrix3d& F, const Eigen::Vector3d& c = Eigen::Vector3d::Zero()) {
  HexCorners x;
  for (std::size_t I = 0; I < 8; ++I) x[I] = F * X[I] + c;
  return x;
}

inline Eigen::Matrix3d rotation() { return Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, -1.0, 0.6).normalized()).toRotationMatrix(); }

// Eigenvalues of K below 1e-10 of the largest in magnitude.
inline int zero_eigenvalues(const HexMatrix& K) {
  const Eigen::SelfAdjointEigenSolver<HexMatrix> es(K);
  const double tol = 1e-10 * es.eigenvalues().cwiseAbs().maxCoeff();
  int n = 0;
  for (int i = 0; i < 24; ++i) n += std::abs(es.eigenvalues()(i)) < tol;
  return n;
}

}  // namespace spifit::element::test
