#pragma once
// The sine law of SPIF (thesis §2.1.8, eq. 2.1 and eq. 9.1): material moves vertically from
// the flat sheet onto a wall of angle alpha (from the horizontal) in plane strain, so the wall
// thickness is t_f = t0 sin(90 deg - alpha) = t0 cos(alpha) (70 deg, 1.2 mm: 0.410 mm), and a
// radial line element of length L0 lands on the wall with length L0 / cos(alpha): its radial
// Green strain is ((1 / cos alpha)^2 - 1) / 2 = tan^2(alpha) / 2 (70 deg: 377 %, thesis §9.4.4,
// Fig. 9.34).
#include <cmath>
#include <numbers>

namespace spifit::scene {

inline double sine_law_thickness(double t0, double wall_angle_deg) {
  return t0 * std::sin((90.0 - wall_angle_deg) * std::numbers::pi / 180.0);
}

inline double sine_law_radial_green_strain(double wall_angle_deg) {
  const double t = std::tan(wall_angle_deg * std::numbers::pi / 180.0);
  return 0.5 * t * t;
}

}  // namespace spifit::scene
