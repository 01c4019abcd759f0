#pragma once
// Loading frame of the material-point scenes: l along the loading direction at angle alpha
// from RD (x), w in the sheet plane (width), z the normal. Material axes stay fixed (no
// spin): strains are integrals of the rate of deformation in these fixed axes, which equals
// the logarithmic strain whenever the principal axes do not rotate (docs/design/numerics-material.md).
#include <Eigen/Core>
#include <cmath>

namespace spifit::scene {

// Q maps an in-plane strain vector (eps_ll, eps_ww, gamma_lw) in the loading frame to the
// material frame (eps_xx, eps_yy, gamma_xy). By work conjugacy, sigma_L = Q^T sigma_M and the
// loading-frame tangent is Q^T D_M Q.
inline Eigen::Matrix3d strain_rotation(double alpha) {
  const double c = std::cos(alpha), s = std::sin(alpha);
  Eigen::Matrix3d Q;
  Q << c * c, s * s, -c * s,
       s * s, c * c, c * s,
       2 * c * s, -2 * c * s, c * c - s * s;
  return Q;
}

// Role of each loading-frame component in a material-point test.
enum class ComponentRole { control, zero_strain, stress_ratio };

struct LoadingControl {
  double alpha = 0.0;  // radians from RD
  int control = 0;     // 0 = ll, 1 = ww, 2 = lw
  ComponentRole role[3] = {ComponentRole::control, ComponentRole::stress_ratio, ComponentRole::stress_ratio};
  double ratio[3] = {0.0, 0.0, 0.0};  // sigma_i = ratio_i * sigma_control for stress_ratio rows
};

}  // namespace spifit::scene
