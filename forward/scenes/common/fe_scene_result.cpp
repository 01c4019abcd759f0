#include "forward/scenes/common/fe_scene_result.hpp"

#include "forward/contact/shell_contact.hpp"

#include <cstdio>

namespace spifit::scene {

void FeSceneResult::take(FeRunOutcome outcome, const ForceLog& force_log, const EnergyLog& energy_log, const contact::ContactOptions& contact,
                         double thickness, double element_size) {
  run = std::move(outcome);
  status = run.status;
  message = run.message;
  wall_seconds = run.wall_seconds;
  force = force_log.history();
  energies = energy_log.table();
  final_energies = energy_log.last();
  ripple = force_ripple(force.samples(), element_size);
  // The penalty's contact points say nothing of the MST contact, which has none.
  const bool penalty = contact.method == contact::ContactOptions::Method::penalty || run.dynamics.is_null();
  for (const std::string& w :
       {penalty ? contact::ShellContact::resolution_warning(force.max_penetration(), force.max_surface_penetration(), contact.points) : "",
        penalty ? contact::ShellContact::penetration_warning(force.max_penetration(), thickness, contact.penalty) : "", ripple_warning(ripple)})
    if (!w.empty()) warnings.push_back(w);
  if (!run.dynamics.is_null()) {
    const double ratio = run.dynamics.value("max_kinetic_over_internal", 0.0);
    if (ratio > kQuasiStaticKineticRatio) {
      char buf[320];
      std::snprintf(buf, sizeof buf,
                    "the explicit run is not quasi-static: its kinetic energy reached %.3g of the internal energy (above %.2g; thesis "
                    "§2.2.3): the forces carry inertia; lower solver.mass_scaling or solver.time_scaling",
                    ratio, kQuasiStaticKineticRatio);
      warnings.push_back(buf);
    }
  }
}

}  // namespace spifit::scene
