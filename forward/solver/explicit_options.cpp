#include "forward/solver/explicit_options.hpp"

#include <cmath>

namespace spifit::solver {

std::string ExplicitOptions::validate() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(mass_scaling)) return "mass_scaling must be > 0";
  if (!positive(rotational_scaling)) return "rotational_mass_scaling must be > 0";
  if (!(std::isfinite(target_time_step) && target_time_step >= 0.0)) return "target_time_step must be >= 0";
  if (!positive(time_scaling)) return "time_scaling must be > 0";
  if (!(std::isfinite(damping) && damping >= 0.0)) return "damping must be >= 0";
  if (!(std::isfinite(bulk_viscosity_linear) && bulk_viscosity_linear >= 0.0 && bulk_viscosity_linear < 1.0))
    return "bulk_viscosity_linear must be in [0, 1)";
  if (!(std::isfinite(bulk_viscosity_quadratic) && bulk_viscosity_quadratic >= 0.0)) return "bulk_viscosity_quadratic must be >= 0";
  if (!(safety > 0.0 && safety <= 1.0)) return "time_step_safety must be in (0, 1]";
  if (!(max_steps >= 1.0)) return "max_steps must be >= 1";
  if (recheck_every < 1) return "recheck_every must be >= 1";
  return {};
}

}  // namespace spifit::solver
