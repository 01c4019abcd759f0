#include "forward/solver/newton_options.hpp"

#include <cmath>
#include <cstdio>

namespace spifit::solver {
namespace {
bool finite_and_increasing(const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || (i > 0 && !(v[i] > v[i - 1]))) return false;
  return true;
}
}  // namespace

std::string NewtonOptions::validate() const {
  if (!(min_increment > 0.0 && min_increment <= initial_increment && initial_increment <= max_increment && max_increment <= 1.0)) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "min_increment %g, initial_increment %g, max_increment %g: need 0 < min <= initial <= max <= 1",
                  min_increment, initial_increment, max_increment);
    return buf;
  }
  if (!(growth >= 1.0)) return "growth must be >= 1";
  if (!(cutback > 0.0 && cutback < 1.0)) return "cutback must be in (0, 1)";
  if (max_iterations < 1) return "max_iterations must be >= 1";
  if (!(force_tolerance > 0.0) || !(displacement_tolerance > 0.0)) return "tolerances must be > 0";
  if (max_line_search < 0) return "max_line_search must be >= 0";
  if (element_chunk < 1) return "element_chunk must be >= 1";
  if (!(stabilisation >= 0.0 && std::isfinite(stabilisation))) return "stabilisation must be >= 0";
  if (!(max_stabilisation == 0.0 || (std::isfinite(max_stabilisation) && max_stabilisation >= stabilisation)))
    return "max_stabilisation must be 0 or >= stabilisation";
  if (stabilised_increments < 1) return "stabilised_increments must be >= 1";
  if (!finite_and_increasing(breakpoints)) return "breakpoints must be finite and increasing";
  if (!finite_and_increasing(restarts)) return "restarts must be finite and increasing";
  return {};
}

}  // namespace spifit::solver
