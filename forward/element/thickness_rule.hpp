#pragma once
// Through-thickness integration of a shell section: Gauss-Legendre points on zeta in [-1, 1]
// (thesis COQJ4: 1 to 11 points, 5 by default). Odd counts put a point on the mid-surface.
// For a fully plastic section the stress jumps at zeta = 0, so the plastic moment is
// integrated inexactly: 5 points give 0.9449 of it, 11 points 0.9875 (tests/.../thickness_rule_test).
#include <vector>

namespace spifit::element {

struct ThicknessRule {
  std::vector<double> zeta;    // in (-1, 1), ascending (bottom to top)
  std::vector<double> weight;  // sum = 2
};

constexpr int kMinThicknessPoints = 1;
constexpr int kMaxThicknessPoints = 11;

// Throws std::invalid_argument outside [1, 11].
ThicknessRule gauss_legendre_rule(int points);

}  // namespace spifit::element
