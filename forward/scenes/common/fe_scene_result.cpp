#include "forward/scenes/common/fe_scene_result.hpp"

#include "forward/contact/shell_contact.hpp"

namespace spifit::scene {

void FeSceneResult::take(FeRunOutcome outcome, const ForceLog& force_log, const EnergyLog& energy_log, int contact_points) {
  run = std::move(outcome);
  status = run.status;
  message = run.message;
  wall_seconds = run.wall_seconds;
  force = force_log.history();
  energies = energy_log.table();
  final_energies = energy_log.last();
  const std::string w = contact::ShellContact::resolution_warning(force.max_penetration(), force.max_surface_penetration(), contact_points);
  if (!w.empty()) warnings.push_back(w);
}

}  // namespace spifit::scene
