#pragma once
// The derivative checker of a scene (in the spirit of Ceres's GradientChecker): the tool force's
// exact parameter derivatives (spifit run --sensitivities) against central differences of whole
// runs with each parameter moved by +-h and +-h/4, at every increment both runs reached at the
// same tool travel. Central differences carry their own error (truncation, and the switches of
// contact points and layers between the runs + h and - h): their spread, |cd(h) - cd(h/4)|, is
// the yardstick the exact derivative is measured against (docs/design/sensitivities.md).
#include "forward/scenes/common/scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace spifit::scene {

struct SensitivityCheckRow {
  std::string name;
  double value = 0.0, step = 0.0;   // the parameter's value and h
  int increments = 0;               // compared (same travel in every run)
  // Largest |exact - cd(h/4)| and |cd(h) - cd(h/4)| over the increments and the force's three
  // components, each over the largest |cd(h/4)| of the run (N per unit of the parameter).
  double difference = 0.0, spread = 0.0;
  int worst_increment = -1;         // where the difference is largest (1-based)
  bool agrees() const { return difference <= spread + 1e-6; }
};

struct SensitivityCheck {
  std::vector<SensitivityCheckRow> rows;
  int runs = 0;
  double tolerance = 0.0;  // the Newton tolerance every run took (0: the scene's own)
  bool agrees() const {
    for (const auto& r : rows)
      if (!r.agrees()) return false;
    return true;
  }
};

// relative_step: h = relative_step x |value| (value 0: relative_step). tolerance > 0: every run's
// implicit solver converges to it (RunControl::newton_tolerance; 0: the scene's own). Central
// differences follow the solver's converged iterates, not the exact solution: at the scenes'
// tolerance 1e-7 they lie up to 2e-5 off the exact derivative at some increments with friction.
// progress (may be empty) is told each run's name as it starts. std::invalid_argument when a run fails (naming it) or the
// scene refuses the parameters (RunControl::sensitivities).
SensitivityCheck check_sensitivities(const Scene& scene, const std::vector<std::string>& names, double relative_step, double tolerance,
                                     const std::function<void(const std::string&)>& progress);

// The table the CLI prints: one row per parameter, and the verdict.
std::string format_sensitivity_check(const SensitivityCheck& c);

}  // namespace spifit::scene
