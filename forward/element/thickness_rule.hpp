#pragma once
// Through-thickness integration of a shell section on zeta in [-1, 1] (thesis COQJ4: 1 to 11
// points, 5 by default).
//  * gauss: Gauss-Legendre (the default, as the thesis: points "close to" the surfaces). Odd
//    counts put a point on the mid-surface. In a fully plastic bent section the stress jumps
//    at zeta = 0, so the plastic moment is integrated inexactly: 5 points give 0.9449 of it,
//    11 points 0.9875 (log_strain_test.cpp).
//  * surface: Gauss-Lobatto on each half of the thickness, sharing the mid-surface point:
//    points on both surfaces and the mid-surface, odd counts 3..11 (5 points = Simpson's rule
//    on each half, Abaqus's default for shells). Exact for the fully plastic moment and for
//    the elastic bending stiffness; surface stresses are sampled at the surfaces.
#include <string>
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

enum class ThicknessRuleKind { gauss, surface };
// "gauss" or "surface"; false otherwise.
bool thickness_rule_from_string(const std::string& s, ThicknessRuleKind* kind);
const char* to_string(ThicknessRuleKind kind);
// Throws std::invalid_argument for an unsupported count (surface: odd, 3 to 11).
ThicknessRule make_thickness_rule(ThicknessRuleKind kind, int points);

}  // namespace spifit::element
