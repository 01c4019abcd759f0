#pragma once
// What the typed result of every FE forming scene holds (forming_result.hpp, cone_result.hpp):
// the skeleton's outcome, the tool force history, the energy account after every increment and
// at the end.
#include "forward/contact/shell_contact.hpp"
#include "forward/io/series.hpp"
#include "forward/model/model_energies.hpp"
#include "forward/scenes/common/energy_log.hpp"
#include "forward/scenes/common/fe_run.hpp"
#include "forward/scenes/common/force_log.hpp"
#include "forward/scenes/common/force_ripple.hpp"
#include "forward/scenes/common/scene_result.hpp"
#include "forward/scenes/common/tool_force_history.hpp"

namespace spifit::scene {

// An explicit run whose kinetic energy exceeds this fraction of the internal energy (once that
// has reached a tenth of its final value) is warned about: thesis §2.2.3 quotes 5 to 10 % as the
// limit of a quasi-static explicit simulation.
inline constexpr double kQuasiStaticKineticRatio = 0.05;

class FeSceneResult : public SceneResult {
 public:
  FeRunOutcome run;
  ToolForceHistory force;
  io::Series energies;
  model::ModelEnergies final_energies;
  ForceRipple ripple;  // over one element length (element_size of take)
  io::Series sensitivities;  // the SensitivityLog's rows; empty without RunControl::sensitivities

  const ToolForceHistory* tool_force() const override { return &force; }
  const io::Series* force_sensitivities() const override { return sensitivities.empty() ? nullptr : &sensitivities; }

  // After the run: its outcome (status, message, wall time), the force and energy logs, the
  // force ripple, and warnings when the tool sank deeper into the tool-side surface than its
  // contact points felt or deeper into the sheet than the penalty should let it (ShellContact's
  // warnings), when the force ripples (ripple_warning), or when an explicit run is not
  // quasi-static (kQuasiStaticKineticRatio).
  void take(FeRunOutcome outcome, const ForceLog& force_log, const EnergyLog& energy_log, const contact::ContactOptions& contact,
            double thickness, double element_size);
};

}  // namespace spifit::scene
